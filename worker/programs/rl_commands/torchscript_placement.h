#pragma once
// The rl positioner's answer from a TorchScript policy folder: its model flown greedily from the
// baseline, in the env of the folder's scenario.json, on the manifest's eval_run.
#include "common/scenario/scenario.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/policy_folder/policy_folder.h"

namespace rlpos::sim {

// `folder.torchscript` must be set; `env` is UavPositioningEnv(folder.trained). Dims that do not
// match the env's spaces, a model.pt that does not load or does not fit, NaN logits: ConfigError
// on --policy naming the file, before any step for all but NaN logits met in flight.
Placement TorchScriptPlacement(const PolicyFolder& folder, UavPositioningEnv& env);

}  // namespace rlpos::sim
