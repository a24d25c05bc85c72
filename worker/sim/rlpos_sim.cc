// rlpos-sim: one experiment on one scenario (the paper's main.py, in C++).
//   rlpos-sim validate FILE
//   rlpos-sim eval --scenario FILE --position x,y,z [--position ...] [--duration S] [--run N]
//                  [--json]
//   rlpos-sim train --scenario FILE [--algorithm dqn|ppo|sac] [--fidelity packet|analytic]
//                   [--seed N] --out DIR [--json]
//   rlpos-sim position --scenario FILE --positioner NAME [--policy DIR] [--json]
//   rlpos-sim describe metrics
// Exit codes: 0 success, 1 runtime failure, 2 bad input (usage, scenario, position),
// 3 ns-3 aborted the simulation.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "config/config_error.h"
#include "sim/abort_guard.h"
#include "sim/commands.h"

namespace {

using rlpos::sim::CommonOptions;

void AddScenarioOverrides(CLI::App* command, CommonOptions& options) {
  command
      ->add_option("--set", options.overrides,
                   "Override a scenario field: path=value (e.g. wifi.mode=adhoc); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--log-level", options.log_level, "error|warning|info|debug")
      ->check(CLI::IsMember({"error", "warning", "info", "debug"}));
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rlpos::sim;
  rlpos::InstallAbortGuard("rlpos-sim", kExitNs3Abort);
  CLI::App app{"rlpos-sim: train, position and evaluate a UAV in ns-3 scenarios"};
  app.require_subcommand(1);
  CommonOptions options;

  auto* validate = app.add_subcommand("validate", "Check a scenario and print a summary");
  validate->add_option("file", options.scenario_file, "Scenario JSON")->required();
  bool validate_json = false;
  validate->add_flag("--json", validate_json, "Print the summary as JSON");
  AddScenarioOverrides(validate, options);

  auto* eval = app.add_subcommand("eval", "Simulate the UAV fixed at a position; print metrics");
  EvalOptions eval_options;
  eval_options.progress = isatty(STDERR_FILENO) != 0;
  eval->add_option("--scenario", options.scenario_file, "Scenario JSON")->required();
  eval->add_option("--position", eval_options.positions,
                   "UAV position x,y,z (m); once per UAV, in the scenario's order")
      ->required();
  eval->add_option("--duration", eval_options.duration,
                   "Simulated seconds (overrides simulation.duration)")
      ->check(CLI::PositiveNumber);
  eval->add_option("--run,--RngRun", eval_options.run, "ns-3 RngRun (overrides simulation.run)")
      ->check(CLI::NonNegativeNumber);
  eval->add_flag("--json", eval_options.json, "Print the metrics as JSON");
  eval->add_flag("--progress,!--no-progress", eval_options.progress,
                 "Progress on stderr (default: on a TTY)");
  AddScenarioOverrides(eval, options);

  auto* train =
      app.add_subcommand("train", "Train the agent; write policy, learning curve, result");
  TrainOptions train_options;
  train->add_option("--scenario", options.scenario_file, "Scenario JSON")->required();
  train->add_option("--algorithm", train_options.algorithm,
                    "dqn|ppo|sac (default: agent.algorithm); sac acts on the continuous action "
                    "space")
      ->check(CLI::IsMember({"dqn", "ppo", "sac"}));
  train->add_option("--fidelity", train_options.fidelity, "packet|analytic (default: env.fidelity)")
      ->check(CLI::IsMember({"packet", "analytic"}));
  train->add_option("--seed", train_options.seed, "Agent seed (default: agent.seed)")
      ->check(CLI::NonNegativeNumber);
  train->add_option("--episodes", train_options.episodes, "Training episodes")
      ->check(CLI::PositiveNumber);
  train->add_option("--out", train_options.out, "Output folder (must not exist)")->required();
  train->add_flag("--json", train_options.json, "Print the result as JSON");
  AddScenarioOverrides(train, options);

  auto* position = app.add_subcommand("position", "Where a positioner puts the UAV");
  PositionOptions position_options;
  position->add_option("--scenario", options.scenario_file, "Scenario JSON")->required();
  position
      ->add_option("--positioner", position_options.positioner,
                   "baseline|centroid|oracle|rl|offsets")
      ->required()
      ->check(CLI::IsMember({"baseline", "centroid", "oracle", "rl", "offsets"}));
  position->add_option("--policy", position_options.policy,
                       "Folder written by train (rl; offsets around the rl position)");
  position->add_option("--from", position_options.from, "offsets: around this x,y,z");
  position->add_option("--offset", position_options.offset,
                       "offsets: position 1-5 (10 m towards +x, -x, +y, -y, +z)");
  position->add_flag("--json", position_options.json, "Print the result as JSON");
  AddScenarioOverrides(position, options);

  auto* describe = app.add_subcommand("describe", "Print a table of the docs as Markdown");
  std::string describe_what;
  describe->add_option("table", describe_what, "metrics: the eval metrics")
      ->required()
      ->check(CLI::IsMember({"metrics"}));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (*validate)
      return RunValidate(options, validate_json);
    if (*describe)
      return RunDescribe(describe_what);
    if (*train)
      return RunTrain(options, train_options);
    if (*position)
      return RunPosition(options, position_options);
    return RunEval(options, eval_options);
  } catch (const rlpos::ConfigError& e) {
    const bool cli = e.path().rfind("--", 0) == 0;
    std::cerr << "rlpos-sim: error: " << (cli ? "" : options.scenario_file + ": ") << e.describe()
              << std::endl;
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-sim: error: " << e.what() << std::endl;
    return kExitRuntime;
  }
}
