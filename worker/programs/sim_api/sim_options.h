#pragma once
// What rlpos-sim and the RL module it loads (worker/programs/rl_commands) share: the subcommands'
// options, the exit codes and how a command loads its scenario. The module's entry point is
// rl_plugin_api.h.
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

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

// Loads the scenario with `extra` overrides first, then the user's --set ones, and sets the log
// level (the option's, else the scenario's).
Scenario LoadScenarioFor(const CommonOptions& options, std::vector<std::string> extra);

struct EvalOptions {
  std::vector<std::string> positions;  // x,y,z per UAV
  std::optional<double> duration;      // unset: the scenario's simulation.duration
  std::optional<long long> run;        // unset: the scenario's simulation.run
  bool json = false;
  bool progress = false;
};

// rlpos-sim train's command line (a campaign file's "train" section is CampaignTrainSection).
struct TrainOptions {
  // Unset: the scenario's agent.algorithm, env.fidelity, agent.seed, agent.train_episodes.
  std::optional<std::string> algorithm;
  std::optional<std::string> fidelity;
  std::optional<long long> seed;
  std::optional<int> episodes;
  std::string out;
  bool json = false;
  // A policy for any scenario (instead of --scenario): trained on a fresh generated scenario per
  // episode of these styles ("urban,campus"), or on the scenarios of a folder.
  std::string generated;
  std::string scenarios_dir;
  std::string uavs = "1";  // --generated: UAV counts, "1" or "1-3"
  std::string ues;         // --generated: UE counts, "6-16" (empty: the generator's default)
  std::optional<long long> steps;  // env steps to train on (--generated, --scenarios)
  // Unset: the training's own (GeneralistOptions, worker/learning/training).
  std::optional<int> validation_scenarios;
  double checkpoint_seconds = 60;  // between checkpoints (--generated, --scenarios)
};

struct PositionOptions {
  std::string positioner;
  std::string policy;  // rl, or offsets around the rl position
  std::string from;    // offsets: around this x,y,z instead
  int offset = 0;      // offsets: which of positions 1-5
  bool json = false;
};

}  // namespace rlpos::sim
