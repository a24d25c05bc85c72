#include "worker/learning/agent_base/dense_network.h"

#include <algorithm>
#include <stdexcept>

// The loops below are element by element (no sum is reordered) and this file is built with
// -ffp-contract=off (no fused multiply-add), so an AVX2 copy computes the same floats as the
// baseline SSE2 one, only wider: the loader picks the copy the CPU runs, the bytes stay the same.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RLPOS_WIDE_LOOPS __attribute__((target_clones("avx2", "default")))
#else
#define RLPOS_WIDE_LOOPS
#endif

namespace rlpos {

DenseNetwork::DenseNetwork(std::vector<int> sizes, bool relu_output)
    : sizes_(std::move(sizes)), relu_output_(relu_output) {
  if (sizes_.size() < 2 || std::any_of(sizes_.begin(), sizes_.end(), [](int s) { return s <= 0; }))
    throw std::invalid_argument("DenseNetwork: at least an input and an output width, all > 0");
  std::size_t offset = 0;
  for (int l = 0; l < LayerCount(); ++l) {
    weight_offset_.push_back(offset);
    offset += static_cast<std::size_t>(LayerInputs(l)) * static_cast<std::size_t>(LayerOutputs(l));
    bias_offset_.push_back(offset);
    offset += static_cast<std::size_t>(LayerOutputs(l));
  }
  parameters_.assign(offset, 0.0f);
  gradients_.assign(offset, 0.0f);
  inputs_.resize(static_cast<std::size_t>(LayerCount()));
}

RLPOS_WIDE_LOOPS void DenseNetwork::SetLayer(int layer, const float* weight_out_in,
                                             const float* bias) {
  const int in = LayerInputs(layer);
  const int out = LayerOutputs(layer);
  for (int i = 0; i < in; ++i) {
    for (int o = 0; o < out; ++o)
      parameters_[WeightOffset(layer) + static_cast<std::size_t>(i * out + o)] =
          weight_out_in[static_cast<std::size_t>(o) * static_cast<std::size_t>(in) +
                        static_cast<std::size_t>(i)];
  }
  std::copy(bias, bias + out, parameters_.begin() + static_cast<long>(BiasOffset(layer)));
}

void DenseNetwork::Forward(const float* x, int rows, float* out) {
  if (rows <= 0)
    throw std::invalid_argument("DenseNetwork::Forward: no rows");
  rows_ = rows;
  inputs_[0].assign(x, x + static_cast<std::size_t>(rows) * static_cast<std::size_t>(InputSize()));
  for (int l = 0; l < LayerCount(); ++l) {
    const int in = LayerInputs(l);
    const int width = LayerOutputs(l);
    const bool last = l + 1 == LayerCount();
    std::vector<float>* next = last ? nullptr : &inputs_[static_cast<std::size_t>(l) + 1];
    if (next)
      next->resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(width));
    float* y_all = last ? out : next->data();
    const float* w = parameters_.data() + WeightOffset(l);
    const float* b = parameters_.data() + BiasOffset(l);
    const float* x_all = inputs_[static_cast<std::size_t>(l)].data();
    for (int r = 0; r < rows; ++r) {
      float* y = y_all + static_cast<std::ptrdiff_t>(r) * width;
      const float* xr = x_all + static_cast<std::ptrdiff_t>(r) * in;
      std::copy(b, b + width, y);
      for (int i = 0; i < in; ++i) {
        const float xi = xr[i];
        if (xi == 0.0f)
          continue;  // a ReLU's zero adds nothing
        const float* wi = w + static_cast<std::ptrdiff_t>(i) * width;
        for (int o = 0; o < width; ++o)
          y[o] += xi * wi[o];
      }
      if (!last || relu_output_) {
        for (int o = 0; o < width; ++o)
          y[o] = y[o] > 0.0f ? y[o] : 0.0f;
      }
    }
  }
  if (relu_output_)
    outputs_.assign(out,
                    out + static_cast<std::size_t>(rows) * static_cast<std::size_t>(OutputSize()));
}

RLPOS_WIDE_LOOPS void DenseNetwork::Backward(const float* d_out, float* d_input) {
  if (rows_ <= 0)
    throw std::logic_error("DenseNetwork::Backward before Forward");
  const int rows = rows_;
  std::fill(gradients_.begin(), gradients_.end(), 0.0f);
  delta_.assign(d_out,
                d_out + static_cast<std::size_t>(rows) * static_cast<std::size_t>(OutputSize()));
  if (relu_output_) {  // through the output's ReLU: 0 where it clipped
    for (std::size_t i = 0; i < delta_.size(); ++i)
      delta_[i] = outputs_[i] > 0.0f ? delta_[i] : 0.0f;
  }
  for (int l = LayerCount() - 1; l >= 0; --l) {
    const int in = LayerInputs(l);
    const int width = LayerOutputs(l);
    const float* x_all = inputs_[static_cast<std::size_t>(l)].data();
    float* dw = gradients_.data() + WeightOffset(l);
    float* db = gradients_.data() + BiasOffset(l);
    for (int r = 0; r < rows; ++r) {
      const float* d = delta_.data() + static_cast<std::ptrdiff_t>(r) * width;
      const float* xr = x_all + static_cast<std::ptrdiff_t>(r) * in;
      for (int o = 0; o < width; ++o)
        db[o] += d[o];
      for (int i = 0; i < in; ++i) {
        const float xi = xr[i];
        if (xi == 0.0f)
          continue;
        float* dwi = dw + static_cast<std::ptrdiff_t>(i) * width;
        for (int o = 0; o < width; ++o)
          dwi[o] += xi * d[o];
      }
    }
    if (l == 0 && !d_input)
      break;  // the input's gradient is not wanted
    // d loss / d (layer l's input), through the ReLU that made it: 0 where it was clipped
    // (the network's own input went through none).
    // Row by row, summed over the outputs in order (each sum as a dot product would add them),
    // but a whole input row at a time from the transposed weights, so that it vectorises.
    const float* w = parameters_.data() + WeightOffset(l);
    weights_by_output_.resize(static_cast<std::size_t>(in) * static_cast<std::size_t>(width));
    for (int i = 0; i < in; ++i) {
      for (int o = 0; o < width; ++o)
        weights_by_output_[static_cast<std::size_t>(o * in + i)] = w[i * width + o];
    }
    delta_below_.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(in), 0.0f);
    for (int r = 0; r < rows; ++r) {
      const float* d = delta_.data() + static_cast<std::ptrdiff_t>(r) * width;
      const float* xr = x_all + static_cast<std::ptrdiff_t>(r) * in;
      float* below = delta_below_.data() + static_cast<std::ptrdiff_t>(r) * in;
      for (int o = 0; o < width; ++o) {
        const float d_o = d[o];
        const float* wo = weights_by_output_.data() + static_cast<std::ptrdiff_t>(o) * in;
        for (int i = 0; i < in; ++i)
          below[i] += wo[i] * d_o;
      }
      if (l == 0)
        continue;
      for (int i = 0; i < in; ++i)
        below[i] = xr[i] > 0.0f ? below[i] : 0.0f;
    }
    if (l == 0) {
      std::copy(delta_below_.begin(), delta_below_.end(), d_input);
      break;
    }
    delta_.swap(delta_below_);
  }
}

}  // namespace rlpos
