#pragma once
// A greedy policy exported from PyTorch as TorchScript: forward(float32 [B, D]) -> logits
// float32 [B, A]. It only acts (no learning, no exploration), so it is not an Agent. libtorch's
// JIT stays in torchscript_policy.cc.
#include <memory>
#include <string>
#include <vector>

#include "worker/env/gym/spaces.h"

namespace rlpos {

class TorchScriptPolicy {
 public:
  // Loads `file` onto the CPU and checks that one forward pass on a zero observation gives
  // [1, action_count] finite float logits. Throws std::invalid_argument with a one-line problem
  // (the caller names the file) if it does not load or does not fit.
  TorchScriptPolicy(const std::string& file, int observation_dim, int action_count);
  ~TorchScriptPolicy();
  TorchScriptPolicy(const TorchScriptPolicy&) = delete;
  TorchScriptPolicy& operator=(const TorchScriptPolicy&) = delete;

  // The logits of one observation (observation_dim floats). Throws std::invalid_argument on
  // output of the wrong shape or type, or a NaN.
  std::vector<float> Logits(const std::vector<float>& observation) const;
  // The allowed action (mask empty: every one) of the highest logit, the first of equals.
  // Throws std::invalid_argument as Logits does, or when the mask allows none.
  int GreedyAction(const std::vector<float>& observation, const ActionMask& mask) const;

 private:
  struct Module;
  std::unique_ptr<Module> module_;
  int observation_dim_;
  int action_count_;
};

}  // namespace rlpos
