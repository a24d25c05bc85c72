#pragma once
// rlpos-sim train --generated STYLES | --scenarios DIR: one policy for any scenario.
#include "worker/programs/sim_api/sim_options.h"

namespace rlpos::sim {

// Whether the options ask for a policy for any scenario (--generated or --scenarios).
bool TrainsAcrossScenarios(const TrainOptions& train);

// Trains it and writes its folder (policy, learning_curve.csv, result.json with "general": true,
// scenario.json with the env and agent settings it was trained with).
int GeneralistTrainCommand(const CommonOptions& options, const TrainOptions& train);

}  // namespace rlpos::sim
