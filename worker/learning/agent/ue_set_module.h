#pragma once
// libtorch's twin of UeSetNetwork (ue_set_network.h): a module holding the UE encoder phi and the
// head rho, which libtorch initialises, saves and loads while UeSetNetwork computes, as MakeMlp's
// networks are to DenseNetwork. Saved, its parameters are "phi.*" and "rho.*".
#include <optional>
#include <string>
#include <vector>

#include "worker/env/gym/spaces.h"
#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent_base/ue_set_network.h"

namespace rlpos {

class UeSetModuleImpl : public torch::nn::Module {
 public:
  // The shapes of UeSetNetwork's constructor; phi's layers are initialised before rho's.
  UeSetModuleImpl(int input_size, SlotBlock slots, const std::vector<int>& encoder,
                  const std::vector<int>& hidden, int out);
  // x[rows][input_size] -> [rows][out]: what UeSetNetwork::Forward computes, with autograd.
  torch::Tensor forward(const torch::Tensor& x);

  torch::nn::Sequential phi{nullptr};
  torch::nn::Sequential rho{nullptr};

 private:
  SlotBlock slots_;
};
TORCH_MODULE(UeSetModule);

// Between the module and a UeSetNetwork of the same shapes (std::invalid_argument if they
// differ), both ways: nothing is lost.
void CopyParameters(const UeSetModule& from, UeSetNetwork& to);
void CopyParameters(const UeSetNetwork& from, UeSetModule& to);

// Whether `file` (a saved network) holds a UE encoder: a UeSetModule's, not a MakeMlp network's.
// Nothing for a file that is not a saved network at all.
std::optional<bool> SavedWithUeEncoder(const std::string& file);

}  // namespace rlpos
