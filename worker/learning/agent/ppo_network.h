#pragma once
// One of PPO's networks (the actor or the critic) with its libtorch twin: an MLP over the whole
// observation (DenseNetwork and MakeMlp's network), or, with agent.ue_encoder, one that takes
// the UE slots as a set (UeSetNetwork and UeSetModule). The plain-float one computes; libtorch
// initialises (at construction, from torch's generator as seeded by the caller), saves and loads.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "worker/env/gym/spaces.h"
#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/ue_set_module.h"
#include "worker/learning/agent_base/dense_network.h"
#include "worker/learning/agent_base/ue_set_network.h"

namespace rlpos {

class PpoNetwork {
 public:
  // ue_encoder empty: the MLP in -> hidden -> out. Otherwise the set network over ue_slots,
  // which it then needs (std::invalid_argument without).
  PpoNetwork(int in, const std::vector<int>& hidden, int out, const std::vector<int>& ue_encoder,
             const std::optional<SlotBlock>& ue_slots);

  void Forward(const float* x, int rows, float* out);
  void Backward(const float* d_out);
  // The plain-float network's (the set network's: phi's, then rho's).
  std::vector<float>& Parameters();
  const std::vector<float>& Parameters() const;
  std::vector<float>& Gradients();

  // Writes the parameters to `file` through the torch twin.
  void Save(const std::string& file);
  // Reads `file` (saved by a network of the same shape). std::runtime_error naming the file when
  // it is missing, not a saved network, with or without a UE encoder unlike this one, or of other
  // widths.
  void Load(const std::string& file);

 private:
  void LoadSet(const std::string& file);

  int in_;
  std::vector<int> hidden_;
  int out_;
  std::vector<int> ue_encoder_;
  SlotBlock ue_slots_;
  // One of the two pairs.
  std::unique_ptr<DenseNetwork> mlp_;
  torch::nn::Sequential mlp_torch_{nullptr};
  std::unique_ptr<UeSetNetwork> set_;
  UeSetModule set_torch_{nullptr};
};

}  // namespace rlpos
