#pragma once
// The rlpos-sim subcommands. Each returns the process exit code; bad input throws ConfigError.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/logging/log.h"
#include "common/scenario/scenario.h"
#include "worker/environment/scenario_loading.h"

namespace rlpos::sim {

constexpr int kExitOk = 0;
constexpr int kExitRuntime = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNs3Abort = 3;

struct CommonOptions {
  std::string scenario_file;
  std::vector<std::string> overrides;  // --set path=value
  std::string log_level;
};

// Loads the scenario with `extra` overrides first, then the user's --set ones. Inline: the
// program and the RL module it loads both use it.
inline Scenario LoadScenarioFor(const CommonOptions& options, std::vector<std::string> extra) {
  std::vector<std::string> overrides = std::move(extra);
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  Scenario scenario = LoadScenario(options.scenario_file, overrides);
  SetLogLevel(ParseLogLevel(options.log_level.empty() ? scenario.log_level : options.log_level));
  return scenario;
}

struct EvalOptions {
  std::vector<std::string> positions;  // x,y,z per UAV
  double duration = -1;
  long long run = -1;
  bool json = false;
  bool progress = false;
};

struct TrainOptions {
  std::string algorithm;  // empty: the scenario's agent.algorithm
  std::string fidelity;   // empty: the scenario's env.fidelity
  long long seed = -1;    // -1: the scenario's agent.seed
  int episodes = -1;      // -1: the scenario's agent.train_episodes
  std::string out;
  bool json = false;
};

struct PositionOptions {
  std::string positioner;
  std::string policy;  // rl, or offsets around the rl position
  std::string from;    // offsets: around this x,y,z instead
  int offset = 0;      // offsets: which of positions 1-5
  bool json = false;
};

int RunValidate(const CommonOptions& options, bool json);
int RunEval(const CommonOptions& options, const EvalOptions& eval);
int RunTrain(const CommonOptions& options, const TrainOptions& train);
int RunPosition(const CommonOptions& options, const PositionOptions& position);
// The rl positioner: the trained policy's greedy final placement (from the RL module), replayed
// in the scenario it was trained on. A scenario (options) that contradicts it is a ConfigError.
Placement RlPlacement(const CommonOptions& options, const std::string& policy);

}  // namespace rlpos::sim
