#pragma once
// Inside the RL module: the implementations behind RlCommands.
#include <string>

#include "common/scenario/scenario.h"
#include "worker/sim_api/sim_options.h"

namespace rlpos::sim {

int TrainCommand(const CommonOptions& options, const TrainOptions& train);
// The trained policy's greedy final position, replayed from the policy folder.
Placement PolicyPlacement(const Scenario& scenario, const std::string& policy);

}  // namespace rlpos::sim
