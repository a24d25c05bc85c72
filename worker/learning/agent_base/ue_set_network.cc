#include "worker/learning/agent_base/ue_set_network.h"

#include <algorithm>
#include <stdexcept>

namespace rlpos {
namespace {

std::vector<int> Widths(int in, const std::vector<int>& layers, int out) {
  std::vector<int> widths{in};
  widths.insert(widths.end(), layers.begin(), layers.end());
  if (out > 0)
    widths.push_back(out);
  return widths;
}

SlotBlock Checked(int input_size, SlotBlock slots, const std::vector<int>& encoder) {
  if (slots.count <= 0 || slots.width <= 0 || slots.offset < 0 ||
      slots.offset + slots.count * slots.width > input_size)
    throw std::invalid_argument("UeSetNetwork: the UE slots do not lie within the input");
  if (encoder.empty())
    throw std::invalid_argument("UeSetNetwork: the encoder needs at least one layer");
  return slots;
}

}  // namespace

UeSetNetwork::UeSetNetwork(int input_size, SlotBlock slots, const std::vector<int>& encoder,
                           const std::vector<int>& hidden, int out)
    : input_size_(input_size),
      slots_(Checked(input_size, slots, encoder)),
      encoder_(Widths(slots.width, encoder, 0), true),
      head_(Widths(input_size - slots.count * slots.width + encoder.back(), hidden, out)) {
  parameters_.assign(encoder_.Parameters().size() + head_.Parameters().size(), 0.0f);
  gradients_.assign(parameters_.size(), 0.0f);
}

std::vector<int> UeSetNetwork::EncoderSizes() const {
  std::vector<int> sizes;
  for (int l = 0; l < encoder_.LayerCount(); ++l)
    sizes.push_back(encoder_.LayerInputs(l));
  sizes.push_back(encoder_.OutputSize());
  return sizes;
}

std::vector<int> UeSetNetwork::HeadSizes() const {
  std::vector<int> sizes;
  for (int l = 0; l < head_.LayerCount(); ++l)
    sizes.push_back(head_.LayerInputs(l));
  sizes.push_back(head_.OutputSize());
  return sizes;
}

void UeSetNetwork::Sync() {
  if (!stale_)
    return;
  const auto split = parameters_.begin() + static_cast<long>(EncoderParameterCount());
  std::copy(parameters_.begin(), split, encoder_.Parameters().begin());
  std::copy(split, parameters_.end(), head_.Parameters().begin());
  stale_ = false;
}

void UeSetNetwork::Forward(const float* x, int rows, float* out) {
  if (rows <= 0)
    throw std::invalid_argument("UeSetNetwork::Forward: no rows");
  Sync();
  rows_ = rows;
  const int width = slots_.width;
  const int encoding = encoder_.OutputSize();
  const int block_end = slots_.offset + slots_.count * width;
  const int head_in = head_.InputSize();

  // The present slots, gathered: only they go through phi.
  present_.assign(static_cast<std::size_t>(rows), 0);
  slot_inputs_.clear();
  for (int r = 0; r < rows; ++r) {
    const float* row = x + static_cast<std::ptrdiff_t>(r) * input_size_;
    for (int k = 0; k < slots_.count; ++k) {
      const float* slot = row + slots_.offset + k * width;
      if (slot[0] > 0.0f) {
        slot_inputs_.insert(slot_inputs_.end(), slot, slot + width);
        ++present_[static_cast<std::size_t>(r)];
      }
    }
  }
  const int slots_present = static_cast<int>(slot_inputs_.size()) / width;
  encodings_.resize(static_cast<std::size_t>(slots_present) * static_cast<std::size_t>(encoding));
  if (slots_present > 0)
    encoder_.Forward(slot_inputs_.data(), slots_present, encodings_.data());

  // rho's input: the values before the slots, the mean encoding (summed in slot order), the
  // values after them.
  head_inputs_.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(head_in));
  const float* e = encodings_.data();
  for (int r = 0; r < rows; ++r) {
    const float* row = x + static_cast<std::ptrdiff_t>(r) * input_size_;
    float* h = head_inputs_.data() + static_cast<std::ptrdiff_t>(r) * head_in;
    std::copy(row, row + slots_.offset, h);
    float* mean = h + slots_.offset;
    std::fill(mean, mean + encoding, 0.0f);
    const int n = present_[static_cast<std::size_t>(r)];
    for (int p = 0; p < n; ++p, e += encoding) {
      for (int o = 0; o < encoding; ++o)
        mean[o] += e[o];
    }
    if (n > 0) {
      const auto count = static_cast<float>(n);
      for (int o = 0; o < encoding; ++o)
        mean[o] /= count;
    }
    std::copy(row + block_end, row + input_size_, mean + encoding);
  }
  head_.Forward(head_inputs_.data(), rows, out);
}

void UeSetNetwork::Backward(const float* d_out) {
  if (rows_ <= 0)
    throw std::logic_error("UeSetNetwork::Backward before Forward");
  const int encoding = encoder_.OutputSize();
  const int head_in = head_.InputSize();
  d_head_inputs_.resize(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(head_in));
  head_.Backward(d_out, d_head_inputs_.data());

  // Each present slot's encoding gets its row's mean's gradient over the row's count.
  d_encodings_.resize(encodings_.size());
  float* d = d_encodings_.data();
  for (int r = 0; r < rows_; ++r) {
    const float* d_mean =
        d_head_inputs_.data() + static_cast<std::ptrdiff_t>(r) * head_in + slots_.offset;
    const int n = present_[static_cast<std::size_t>(r)];
    const auto count = static_cast<float>(n);
    for (int p = 0; p < n; ++p, d += encoding) {
      for (int o = 0; o < encoding; ++o)
        d[o] = d_mean[o] / count;
    }
  }
  const auto split = gradients_.begin() + static_cast<long>(EncoderParameterCount());
  if (encodings_.empty()) {
    std::fill(gradients_.begin(), split, 0.0f);
  } else {
    encoder_.Backward(d_encodings_.data());
    std::copy(encoder_.Gradients().begin(), encoder_.Gradients().end(), gradients_.begin());
  }
  std::copy(head_.Gradients().begin(), head_.Gradients().end(), split);
}

}  // namespace rlpos
