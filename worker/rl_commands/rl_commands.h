#pragma once
// Inside the RL module: the implementations behind RlCommands.
#include <string>

#include "worker/sim/commands.h"

namespace rlpos::sim {

int TrainCommand(const CommonOptions& options, const TrainOptions& train);
// The trained policy's greedy final position, replayed from the policy folder.
Placement PolicyPlacement(const Scenario& scenario, const std::string& policy);

}  // namespace rlpos::sim
