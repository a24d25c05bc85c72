#pragma once
// Inside the RL module: the implementations behind RlCommands.
#include <string>

#include "common/scenario/scenario.h"
#include "worker/programs/sim_api/rl_plugin_api.h"
#include "worker/programs/sim_api/sim_options.h"

namespace rlpos::sim {

int TrainCommand(const CommonOptions& options, const TrainOptions& train);
// The trained policy's greedy final placement: training's own final evaluation episode, replayed
// from the policy folder alone. The caller's scenario (options) may restate the policy's, not
// contradict it (common/scenario/scenario_contradiction.h).
Placement PolicyPlacement(const CommonOptions& options, const std::string& policy);
// A policy for any scenario, flown online in the caller's scenario (rl_plugin_api.h). Refuses a
// per-scenario or TorchScript policy, and a scenario outside the policy's scope, with a
// ConfigError on --policy.
TrackDecision PolicyTrack(const CommonOptions& options, const std::string& policy);

}  // namespace rlpos::sim
