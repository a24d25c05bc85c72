#pragma once
// The small multilayer perceptrons the agents are made of, what they do with them besides
// forward passes (copy, Polyak-average, load with a shape check), and the batches they feed them.
#include <string>
#include <vector>

#include "worker/env/gym/spaces.h"
#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent_base/dense_network.h"

namespace rlpos {

// in -> hidden... (ReLU after each) -> out, no activation on the output.
torch::nn::Sequential MakeMlp(const std::vector<int>& hidden, int in, int out);

void CopyParameters(const torch::nn::Sequential& from, torch::nn::Sequential& to);
// Between a MakeMlp network and a DenseNetwork of the same widths (std::invalid_argument if they
// differ): libtorch keeps initialising, saving and loading the networks a DenseNetwork computes.
void CopyParameters(const torch::nn::Sequential& from, DenseNetwork& to);
void CopyParameters(const DenseNetwork& from, torch::nn::Sequential& to);
// to <- tau * from + (1 - tau) * to.
void SoftUpdate(const torch::nn::Sequential& from, torch::nn::Sequential& to, double tau);

// Copies of some networks' parameters, put back later: the policy a trainer keeps while the
// agent goes on learning (Agent::KeepPolicy).
class KeptNetworks {
 public:
  void Keep(const std::vector<torch::nn::Sequential>& networks);
  // Into networks of the shapes kept, in the same order. Throws std::logic_error if nothing is
  // kept.
  void Restore(const std::vector<torch::nn::Sequential>& networks) const;

 private:
  std::vector<std::vector<torch::Tensor>> parameters_;  // per network
};

// A 1 x n tensor of an observation (copied).
torch::Tensor Row(const std::vector<float>& values);

// A rows x dim tensor whose row r is the first `dim` values of row_of(r), a std::vector<float>.
template <typename RowOf>
torch::Tensor StackRows(std::size_t rows, int dim, RowOf row_of) {
  torch::Tensor t = torch::empty({static_cast<long>(rows), dim});
  auto a = t.accessor<float, 2>();
  for (std::size_t r = 0; r < rows; ++r) {
    const std::vector<float>& row = row_of(r);
    for (int c = 0; c < dim; ++c)
      a[static_cast<long>(r)][c] = row[static_cast<std::size_t>(c)];
  }
  return t;
}

// `forbidden` where a row's mask forbids the action, 0 elsewhere: added to Q-values or logits,
// it keeps max, argmax and softmax to the allowed actions. A mask that allows nothing counts as
// no mask (a max over nothing has no value).
torch::Tensor MaskPenalty(const std::vector<const ActionMask*>& masks, int actions,
                          float forbidden);

// Loads `file` into `into`, whose shapes it must match. Throws std::runtime_error naming the file
// when it is missing, not a saved network or of another shape.
void LoadNetwork(const std::string& file, torch::nn::Sequential& into,
                 const std::vector<int>& hidden, int in, int out);

}  // namespace rlpos
