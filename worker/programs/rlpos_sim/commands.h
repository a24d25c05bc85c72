#pragma once
// The rlpos-sim subcommands. Each returns the process exit code; bad input throws ConfigError.
// Their options and exit codes are in worker/programs/sim_api, which the RL module shares.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/programs/sim_api/rl_plugin_api.h"
#include "worker/programs/sim_api/sim_options.h"

namespace rlpos::sim {

// The help of every option that takes a scenario: a path, or a shipped one's name
// (common/process/shipped_data.h).
inline constexpr const char* kScenarioHelp = "Scenario JSON, or a shipped scenario's name (b)";

int RunValidate(const CommonOptions& options, bool json);
int RunEval(const CommonOptions& options, const EvalOptions& eval);
int RunTrain(const CommonOptions& options, const TrainOptions& train);
int RunPosition(const CommonOptions& options, const PositionOptions& position);
// The rl positioner: the trained policy's greedy final placement (from the RL module), replayed
// in the scenario it was trained on. A scenario (options) that contradicts it is a ConfigError.
Placement RlPlacement(const CommonOptions& options, const std::string& policy);
// The rl positioner online (track): a policy for any scenario, flown at each decision (from the
// RL module). A per-scenario policy, or a scenario outside its scope, is a ConfigError.
TrackDecision RlTrackDecision(const CommonOptions& options, const std::string& policy);

}  // namespace rlpos::sim
