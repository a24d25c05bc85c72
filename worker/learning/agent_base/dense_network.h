#pragma once
// A small multilayer perceptron in plain float arithmetic: in -> hidden... (ReLU after each) ->
// out, the shape MakeMlp gives (optionally with a ReLU on the output too), with its forward pass
// and the gradient of its parameters (and of its input, for a network in front of it).
//
// Why not libtorch: PPO's networks are 32-64 units wide and learn from minibatches of 64 rows.
// At that size a libtorch update is dispatch, not arithmetic (about 1.4 ms of op overhead for
// 0.1 ms of sums), so PPO trained 75 % of its time in it. Here a forward pass is a few loops.
// Every sum runs in a fixed order and the file is built without contraction into FMA, so the
// same parameters and inputs give the same bits on every x86-64 CPU, whatever its vector width.
#include <cstddef>
#include <vector>

namespace rlpos {

class DenseNetwork {
 public:
  // sizes: the input width, the hidden widths, the output width (at least two entries, all > 0).
  // relu_output: a ReLU after the last layer as well (a layer whose output feeds another network).
  // Parameters start at 0: load them (CopyParameters, from a torch network) before use.
  explicit DenseNetwork(std::vector<int> sizes, bool relu_output = false);

  int InputSize() const { return sizes_.front(); }
  int OutputSize() const { return sizes_.back(); }
  int LayerCount() const { return static_cast<int>(sizes_.size()) - 1; }
  int LayerInputs(int layer) const { return sizes_[static_cast<std::size_t>(layer)]; }
  int LayerOutputs(int layer) const { return sizes_[static_cast<std::size_t>(layer) + 1]; }

  // Every layer's weights, then its bias, layer after layer. A layer's weights are stored
  // input-major ([in][out], the transpose of torch's Linear weight) so that a forward pass adds
  // whole rows, which vectorises without reordering any sum.
  std::vector<float>& Parameters() { return parameters_; }
  const std::vector<float>& Parameters() const { return parameters_; }
  std::size_t WeightOffset(int layer) const {
    return weight_offset_[static_cast<std::size_t>(layer)];
  }
  std::size_t BiasOffset(int layer) const { return bias_offset_[static_cast<std::size_t>(layer)]; }
  // Sets layer `layer` from torch's Linear layout: weight [out][in] and bias [out], row-major.
  void SetLayer(int layer, const float* weight_out_in, const float* bias);

  // out[rows][OutputSize()] for x[rows][InputSize()], both row-major. Keeps the layers' inputs
  // for Backward.
  void Forward(const float* x, int rows, float* out);
  // d_out[rows][OutputSize()]: d loss / d output for the rows of the last Forward. Sets
  // Gradients() to d loss / d parameters (same layout as Parameters()), and, given d_input
  // [rows][InputSize()], d loss / d input there. The parameters' gradients are the same bits
  // with or without d_input.
  void Backward(const float* d_out, float* d_input = nullptr);
  std::vector<float>& Gradients() { return gradients_; }
  const std::vector<float>& Gradients() const { return gradients_; }

 private:
  std::vector<int> sizes_;
  bool relu_output_;
  std::vector<std::size_t> weight_offset_;
  std::vector<std::size_t> bias_offset_;
  std::vector<float> parameters_;
  std::vector<float> gradients_;
  // inputs_[l]: layer l's input for the rows of the last Forward (inputs_[0] is x; after that
  // the previous layer's output after its ReLU).
  std::vector<std::vector<float>> inputs_;
  std::vector<float> outputs_;  // the last Forward's output, kept with relu_output only
  std::vector<float> delta_;
  std::vector<float> delta_below_;
  std::vector<float> weights_by_output_;  // a layer's weights [out][in], for Backward
  int rows_ = 0;
};

}  // namespace rlpos
