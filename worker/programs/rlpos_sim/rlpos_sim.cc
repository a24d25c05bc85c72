// rlpos-sim: one experiment on one scenario (the paper's main.py, in C++).
//   rlpos-sim validate FILE
//   rlpos-sim eval --scenario FILE --position x,y,z [--position ...] [--duration S] [--run N]
//                  [--json]
//   rlpos-sim train --scenario FILE [--algorithm dqn|ppo|sac] [--fidelity packet|analytic]
//                   [--seed N] --out DIR [--json]
//   rlpos-sim train --generated STYLE[,STYLE...] | --scenarios DIR [--uavs K|K-L] [--ues M-N]
//                   --steps N [--seed N] --out DIR [--json]
//   rlpos-sim position --scenario FILE --positioner NAME [--policy DIR] [--json]
//   rlpos-sim track --scenario FILE --positioner NAME --duration S --RngRun N
//                   [--fidelity analytic] [--json]
//   rlpos-sim describe metrics | track-metrics | hyperparameters [--algorithm A] | settings
//   rlpos-sim import --from rlpos3 CONFIG.json [--out FILE]
//   rlpos-sim import --from osm|geojson FILE --center LAT,LON --size WxD [--ues N] [--out FILE]
//   rlpos-sim render SCENARIO [--position x,y,z]... [--result FILE] [--side] --out FILE.png|.svg
//   rlpos-sim generate --seed N [--style urban|campus|suburb|open] [--uavs K] [--ues M]
//                      [--out FILE]
// Exit codes: 0 success, 1 runtime failure, 2 bad input (usage, scenario, position),
// 3 ns-3 aborted the simulation.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "common/command_line/parse_error.h"
#include "common/command_line/version_flag.h"
#include "common/config/config_error.h"
#include "common/process/shipped_data.h"
#include "common/scenario/names.h"
#include "worker/programs/rlpos_sim/abort_guard.h"
#include "worker/programs/rlpos_sim/commands.h"
#include "worker/programs/rlpos_sim/describe_command.h"
#include "worker/programs/rlpos_sim/generate_command.h"
#include "worker/programs/rlpos_sim/import_command.h"
#include "worker/programs/rlpos_sim/render_command.h"
#include "worker/programs/rlpos_sim/track_command.h"

namespace {

using namespace rlpos::sim;

// What the command line asked for: the subcommands and their options.
struct Invocation {
  CommonOptions options;
  CLI::App* validate = nullptr;
  bool validate_json = false;
  CLI::App* eval = nullptr;
  EvalOptions eval_options;
  CLI::App* train = nullptr;
  TrainOptions train_options;
  CLI::App* position = nullptr;
  PositionOptions position_options;
  TrackCommand track;
  DescribeCommand describe;
  ImportCommand import;
  RenderCommand render;
  GenerateCommand generate;
};

void AddScenarioOverrides(CLI::App* command, CommonOptions& options) {
  command
      ->add_option("--set", options.overrides,
                   "Override a scenario field: path=value (e.g. wifi.mode=adhoc); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--log-level", options.log_level, "error|warning|info|debug")
      ->check(CLI::IsMember({"error", "warning", "info", "debug"}));
}

void AddValidate(CLI::App& app, Invocation& in) {
  in.validate = app.add_subcommand("validate", "Check a scenario and print a summary");
  in.validate->add_option("file", in.options.scenario_file, kScenarioHelp)->required();
  in.validate->add_flag("--json", in.validate_json, "Print the summary as JSON");
  AddScenarioOverrides(in.validate, in.options);
}

void AddEval(CLI::App& app, Invocation& in) {
  in.eval = app.add_subcommand("eval", "Simulate the UAV fixed at a position; print metrics");
  in.eval_options.progress = isatty(STDERR_FILENO) != 0;
  in.eval->add_option("--scenario", in.options.scenario_file, kScenarioHelp)->required();
  in.eval
      ->add_option("--position", in.eval_options.positions,
                   "UAV position x,y,z (m); once per UAV, in the scenario's order")
      ->required();
  in.eval
      ->add_option("--duration", in.eval_options.duration,
                   "Simulated seconds (overrides simulation.duration)")
      ->check(CLI::PositiveNumber);
  in.eval
      ->add_option("--run,--RngRun", in.eval_options.run, "ns-3 RngRun (overrides simulation.run)")
      ->check(CLI::NonNegativeNumber);
  in.eval->add_flag("--json", in.eval_options.json, "Print the metrics as JSON");
  in.eval->add_flag("--progress,!--no-progress", in.eval_options.progress,
                    "Progress on stderr (default: on a TTY)");
  AddScenarioOverrides(in.eval, in.options);
}

void AddTrain(CLI::App& app, Invocation& in) {
  in.train = app.add_subcommand("train", "Train the agent; write policy, learning curve, result");
  in.train->add_option("--scenario", in.options.scenario_file, kScenarioHelp);
  in.train->add_option("--generated", in.train_options.generated,
                       "Train a policy for any scenario, on a fresh generated scenario per "
                       "episode of these styles (urban,campus,suburb,open) instead of --scenario");
  in.train->add_option("--scenarios", in.train_options.scenarios_dir,
                       "Train a policy for any scenario on the scenarios (*.json) of this folder");
  in.train->add_option("--uavs", in.train_options.uavs, "--generated: UAVs, 1 or a range 1-3");
  in.train->add_option("--ues", in.train_options.ues,
                       "--generated: UEs, a count or a range 6-16 (default: the style's)");
  in.train
      ->add_option("--steps", in.train_options.steps,
                   "--generated, --scenarios: env steps to train on")
      ->check(CLI::PositiveNumber);
  in.train
      ->add_option("--validation-scenarios", in.train_options.validation_scenarios,
                   "--generated, --scenarios: scenarios the kept policy is chosen on (default 24)")
      ->check(CLI::Range(1, 1000));
  in.train
      ->add_option("--checkpoint-every", in.train_options.checkpoint_seconds,
                   "--generated, --scenarios: seconds between checkpoints (default 60); the same "
                   "command resumes from the last")
      ->check(CLI::NonNegativeNumber);
  in.train
      ->add_option("--algorithm", in.train_options.algorithm,
                   rlpos::Choices(rlpos::kAlgorithms) +
                       " (default: agent.algorithm); sac acts on the continuous action space")
      ->check(CLI::IsMember(rlpos::NameList(rlpos::kAlgorithms)));
  in.train
      ->add_option("--fidelity", in.train_options.fidelity,
                   rlpos::Choices(rlpos::kFidelities) + " (default: env.fidelity)")
      ->check(CLI::IsMember(rlpos::NameList(rlpos::kFidelities)));
  in.train->add_option("--seed", in.train_options.seed, "Agent seed (default: agent.seed)")
      ->check(CLI::NonNegativeNumber);
  in.train->add_option("--episodes", in.train_options.episodes, "Training episodes")
      ->check(CLI::PositiveNumber);
  in.train->add_option("--out", in.train_options.out, "Output folder (must not exist)")->required();
  in.train->add_flag("--json", in.train_options.json, "Print the result as JSON");
  AddScenarioOverrides(in.train, in.options);
}

void AddPosition(CLI::App& app, Invocation& in) {
  in.position = app.add_subcommand("position", "Where a positioner puts the UAV");
  in.position->add_option("--scenario", in.options.scenario_file, kScenarioHelp)->required();
  in.position
      ->add_option("--positioner", in.position_options.positioner,
                   rlpos::Choices(rlpos::kPositioners))
      ->required()
      ->check(CLI::IsMember(rlpos::NameList(rlpos::kPositioners)));
  in.position->add_option("--policy", in.position_options.policy,
                          "Folder written by train, or a shipped policy's name (generalist-1uav); "
                          "rl, and offsets around the rl position");
  in.position->add_option("--from", in.position_options.from, "offsets: around this x,y,z");
  in.position->add_option("--offset", in.position_options.offset,
                          "offsets: position 1-5 (10 m towards +x, -x, +y, -y, +z)");
  in.position->add_flag("--json", in.position_options.json, "Print the result as JSON");
  AddScenarioOverrides(in.position, in.options);
}

// A shipped scenario or policy may be named instead of given as a path (`--scenario b`).
void ResolveShippedNames(Invocation& in) {
  using rlpos::ResolveShipped, rlpos::ShippedKind;
  if (!*in.import.command)  // import reads another tool's file, never a shipped scenario
    in.options.scenario_file = ResolveShipped(in.options.scenario_file, ShippedKind::kScenario);
  in.position_options.policy = ResolveShipped(in.position_options.policy, ShippedKind::kPolicy);
  in.track.policy = ResolveShipped(in.track.policy, ShippedKind::kPolicy);
}

// Runs the subcommand that was parsed; bad input is one line on stderr and exit code 2.
int Run(Invocation& in) {
  try {
    ResolveShippedNames(in);
    if (*in.validate)
      return RunValidate(in.options, in.validate_json);
    if (*in.describe.command)
      return RunDescribe(in.describe);
    if (*in.import.command)
      return RunImport(in.import, in.options.scenario_file);
    if (*in.generate.command)
      return RunGenerate(in.generate);
    if (*in.train)
      return RunTrain(in.options, in.train_options);
    if (*in.position)
      return RunPosition(in.options, in.position_options);
    if (*in.render.command)
      return RunRender(in.options, in.render);
    if (*in.track.command)
      return RunTrackCommand(in.options, in.track);
    return RunEval(in.options, in.eval_options);
  } catch (const rlpos::ConfigError& e) {
    const bool cli = e.path().rfind("--", 0) == 0;
    std::cerr << "rlpos-sim: error: " << (cli ? "" : in.options.scenario_file + ": ")
              << e.describe() << std::endl;
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-sim: error: " << e.what() << std::endl;
    return kExitRuntime;
  }
}

}  // namespace

int main(int argc, char** argv) {
  rlpos::InstallAbortGuard("rlpos-sim", kExitNs3Abort);
  CLI::App app{"rlpos-sim: train, position and evaluate a UAV in ns-3 scenarios"};
  app.require_subcommand(1);
  rlpos::AddVersionFlag(app, "rlpos-sim");
  Invocation in;
  AddValidate(app, in);
  AddEval(app, in);
  AddTrain(app, in);
  AddPosition(app, in);
  AddTrack(app, in.track, in.options);
  AddScenarioOverrides(in.track.command, in.options);
  AddDescribe(app, in.describe);
  AddImport(app, in.import, in.options.scenario_file);
  AddRender(app, in.render, in.options);
  AddScenarioOverrides(in.render.command, in.options);
  AddGenerate(app, in.generate);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return rlpos::ExitOnParseError(app, "rlpos-sim", e, kExitBadInput);
  }
  return Run(in);
}
