#pragma once
// PPO's networks read back from a file libtorch saved (PpoNetwork::Save) without libtorch
// (saved_tensors.h), into their plain-float form: the MLP of MakeMlp (its Linear layers' weight
// [out][in] and bias [out], in order) or the set network (phi's layers, then rho's). The checks
// and messages of PpoNetwork::Load.
#include <string>

#include "worker/learning/agent_base/dense_network.h"
#include "worker/learning/agent_base/ue_set_network.h"

namespace rlpos {

// std::runtime_error naming `file` when it is missing, not a saved network, with or without a
// UE encoder unlike `net`, or of other widths.
void LoadSavedNetwork(const std::string& file, DenseNetwork& net);
void LoadSavedNetwork(const std::string& file, UeSetNetwork& net);

}  // namespace rlpos
