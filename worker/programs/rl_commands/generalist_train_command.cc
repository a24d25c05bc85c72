// rlpos-sim train --generated STYLES | --scenarios DIR: a policy for any scenario
// (worker/learning/training/generalist_training.h), written as a policy folder that declares itself
// general.
#include "worker/programs/rl_commands/generalist_train_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/config/config_error.h"
#include "common/hash/sha256.h"
#include "common/provenance/provenance.h"
#include "common/scenario/default_sets.h"
#include "common/scenario/names.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/gym/general_observation.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/make_agent.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/policy_folder/policy_folder.h"
#include "worker/learning/training/generalist_training.h"
#include "worker/programs/rl_commands/generalist_checkpoint.h"

namespace rlpos::sim {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::vector<GeneratorStyle> ParseStyles(const std::string& text) {
  std::vector<GeneratorStyle> styles;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ','))
    styles.push_back(ParseStyle(name, "--generated"));
  if (styles.empty())
    throw ConfigError("--generated", "names no style (urban, campus, suburb or open)");
  return styles;
}

std::vector<std::string> StyleNames(const std::vector<GeneratorStyle>& styles) {
  std::vector<std::string> names;
  for (GeneratorStyle s : styles)
    names.push_back(StyleName(s));
  return names;
}

// What every drawn scenario gets before the user's --set: the named default set (default_sets.h)
// and the command's --seed.
std::vector<std::string> GeneralistDefaults(const TrainOptions& t, int max_uavs) {
  std::vector<std::string> o = AnyScenarioDefaults(max_uavs).overrides;
  if (t.seed)
    o.push_back("agent.seed=" + std::to_string(*t.seed));
  return o;
}

// The settings scenario: `document` with the defaults and the user's --set applied, checked as
// any scenario is; then held to what training across scenarios needs.
Scenario SettingsScenario(nlohmann::json document, const std::vector<std::string>& defaults,
                          const std::vector<std::string>& user) {
  std::vector<std::string> overrides = defaults;
  overrides.insert(overrides.end(), user.begin(), user.end());
  Scenario s;
  try {
    ApplyOverrides(document, overrides);
    s = ParseScenario(document);
    CheckScenarioAgainstNs3(s);
  } catch (const ConfigError& e) {
    throw BlameOverride(e, overrides);
  }
  if (s.agent.algorithm != "ppo")
    throw ConfigError("--algorithm", "only ppo trains across scenarios in this version");
  if (s.env.fidelity != "analytic")
    throw ConfigError("--fidelity", "training across scenarios runs at analytic fidelity");
  for (const std::string& field : s.env.observations) {
    if (!IsGeneralObservation(field)) {
      throw ConfigError("--set",
                        "env.observations: \"" + field +
                            "\" is one scenario's own; a policy for any scenario "
                            "observes zone, ues, heights, coverage, lookahead and others only");
    }
  }
  return s;
}

struct Source {
  std::unique_ptr<ScenarioDraw> draw;
  Scenario settings;
  nlohmann::json description;  // what result.json records of the training scenarios
};

Source GeneratedSource(const TrainOptions& t, const std::vector<std::string>& user) {
  GeneratedDistribution d;
  d.styles = ParseStyles(t.generated);
  d.uavs = ParseCountRange(t.uavs, 1, kMaxGeneratedUavs, "--uavs");
  if (!t.ues.empty())
    d.ues = ParseCountRange(t.ues, 1, kMaxGeneratedUes, "--ues");
  GeneratorOptions example;
  example.seed = kValidationSeedBase;
  example.style = d.styles.front();
  example.uavs = d.uavs.max;
  if (d.ues)
    example.ues = d.ues->max;
  Source source;
  source.settings = SettingsScenario(ParseJsonText(GenerateScenario(example).json_text),
                                     GeneralistDefaults(t, d.uavs.max), user);
  source.description = {{"generated", StyleNames(d.styles)},
                        {"uavs", {d.uavs.min, d.uavs.max}},
                        {"ues", d.ues ? nlohmann::json{d.ues->min, d.ues->max} : nullptr}};
  source.draw = std::make_unique<ScenarioDraw>(d, source.settings, source.settings.agent.seed);
  return source;
}

Source FolderSource(const TrainOptions& t, const std::vector<std::string>& user) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(t.scenarios_dir, ec)) {
    if (entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  if (ec)
    throw ConfigError("--scenarios", t.scenarios_dir + ": " + ec.message());
  if (files.empty())
    throw ConfigError("--scenarios", t.scenarios_dir + " holds no *.json scenario");
  std::sort(files.begin(), files.end());
  std::vector<Scenario> set;
  std::vector<std::string> names;
  int max_uavs = 1, min_uavs = 1000;
  for (const fs::path& f : files) {
    Scenario s;
    try {
      s = LoadScenario(f.string(), {});
    } catch (const ConfigError& e) {
      throw ConfigError("--scenarios", f.string() + ": " + e.describe());
    }
    max_uavs = std::max(max_uavs, static_cast<int>(s.uavs.size()));
    min_uavs = std::min(min_uavs, static_cast<int>(s.uavs.size()));
    set.push_back(std::move(s));
    names.push_back(f.filename().string());
  }
  Source source;
  source.settings =
      SettingsScenario(ReadJsonFile(files.front().string()), GeneralistDefaults(t, max_uavs), user);
  source.description = {{"scenarios", names}, {"uavs", {min_uavs, max_uavs}}, {"ues", nullptr}};
  source.draw = std::make_unique<ScenarioDraw>(std::move(set), names, source.settings,
                                               source.settings.agent.seed);
  return source;
}

nlohmann::json ValidationJson(const std::vector<ValidationScore>& scores) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : scores)
    rows.push_back({{"scenario", s.origin},
                    {"reward", s.final_reward},
                    {"oracle_reward", s.oracle_reward},
                    {"ratio", s.ratio},
                    {"n_los", s.n_los},
                    {"n_ues", s.n_ues}});
  return rows;
}

// The option combinations training across scenarios refuses, in the order they are reported.
void CheckGeneralistOptions(const CommonOptions& options, const TrainOptions& t) {
  if (!t.generated.empty() && !t.scenarios_dir.empty())
    throw ConfigError("--generated", "and --scenarios exclude each other");
  if (!options.scenario_file.empty())
    throw ConfigError("--scenario", "trains for one scenario; --generated and --scenarios for any");
  if (!t.steps)
    throw ConfigError("--steps", "is required with --generated and --scenarios");
  if (t.episodes)
    throw ConfigError("--episodes", "counts one scenario's episodes; give --steps instead");
  if (t.algorithm && *t.algorithm != "ppo")
    throw ConfigError("--algorithm", "only ppo trains across scenarios in this version");
  if (t.fidelity && *t.fidelity != "analytic")
    throw ConfigError("--fidelity", "training across scenarios runs at analytic fidelity");
  if (!t.scenarios_dir.empty() && (t.uavs != "1" || !t.ues.empty()))
    throw ConfigError("--uavs", "and --ues shape --generated's draws; --scenarios takes the set's");
}

// One training across scenarios: what it trains on, for how long, and the OUT.partial folder it
// works in until it is done.
struct GeneralistJob {
  const TrainOptions& t;
  long long steps;
  int validation_scenarios;
  const Source& source;
  fs::path partial;
  const GeneralistCheckpoint& checkpoint;
  const std::optional<SavedCheckpoint>& resumed;
};

// What the training is: a checkpoint of anything else is not resumed.
std::string TrainingFingerprint(const Source& source, long long steps, int validation_scenarios) {
  return Sha256Hex(ToJson(source.settings).dump() + source.description.dump() + "|" +
                   std::to_string(steps) + "|" + std::to_string(validation_scenarios));
}

// A fresh OUT.partial, for a training with no checkpoint to go on from.
void CreatePartial(const fs::path& partial) {
  std::error_code ec;
  fs::remove_all(partial, ec);
  if (!fs::create_directories(partial, ec) || ec)
    throw ConfigError("--out", "cannot create " + partial.string() + ": " + ec.message());
}

// Episode e of a training from seed S starts from RngRun S * 1000000 + 1 + e, as per-scenario
// training's (its exploring start).
std::uint64_t FirstEpisodeRun(const Scenario& settings) {
  return settings.agent.seed * 1000000 + 1;
}

void WriteCurveHeader(std::ostream& curve) {
  curve << "steps,episodes,train_final_reward,validation_ratio,validation_worst_ratio,"
           "best_validation_ratio\n";
}

void WriteCurveRow(std::ostream& curve, const GeneralistProgress& p) {
  curve << p.steps << ',' << p.episodes << ',' << p.train_final_reward << ',';
  if (p.validation)
    curve << *p.validation << ',' << *p.validation_worst;
  else
    curve << ',';
  curve << ',';
  if (p.best_validation)
    curve << *p.best_validation;
  curve << '\n';
}

void PrintProgress(const GeneralistProgress& p, long long steps, double elapsed) {
  const double share = std::min(1.0, static_cast<double>(p.steps) / static_cast<double>(steps));
  std::fprintf(stderr, "steps %lld/%lld (%.0f%%), episodes %lld, final reward %.3f",
               static_cast<long long>(p.steps), steps, 100 * share,
               static_cast<long long>(p.episodes), p.train_final_reward);
  if (p.validation)
    std::fprintf(stderr, ", validation %.3f of the oracle, worst %.3f (best mean %.3f)",
                 *p.validation, *p.validation_worst, *p.best_validation);
  std::fprintf(stderr, ", %s, ETA %s\n", FormatDuration(elapsed).c_str(),
               FormatDuration(share > 0 ? elapsed * (1 - share) / share : 0).c_str());
}

// Trains `agent` from the checkpoint, if any, writing the learning curve and checkpoints into
// the partial folder; `seconds` gets the training time, the checkpoint's included.
GeneralistResult TrainInPartial(const GeneralistJob& job, PpoAgent& agent, double& seconds) {
  GeneralistOptions g;
  g.steps = job.steps;
  g.validation_scenarios = job.validation_scenarios;
  const fs::path curve_file = job.partial / "learning_curve.csv";
  std::ofstream curve;
  GeneralistCheckpoints checkpoints;
  double seconds_before = 0.0;
  if (job.resumed) {
    job.checkpoint.LoadAgent(agent);
    // The curve as it stood at the checkpoint: rows written after it are flown again.
    fs::resize_file(curve_file, job.resumed->curve_bytes);
    curve.open(curve_file, std::ios::app);
    checkpoints.resume = &job.resumed->state;
    seconds_before = job.resumed->seconds;
    std::fprintf(stderr, "resuming from the checkpoint in %s: step %lld of %lld\n",
                 job.partial.string().c_str(),
                 static_cast<long long>(job.resumed->state.result.steps), job.steps);
  } else {
    curve.open(curve_file);
    WriteCurveHeader(curve);
  }
  const auto started = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(seconds_before));
  auto last_checkpoint = Clock::now();
  checkpoints.due = [&] {
    return Clock::now() - last_checkpoint >=
           std::chrono::duration<double>(job.t.checkpoint_seconds);
  };
  checkpoints.save = [&](const GeneralistState& state) {
    curve.flush();
    const double elapsed = std::chrono::duration<double>(Clock::now() - started).count();
    job.checkpoint.Save(state, agent, static_cast<std::uint64_t>(fs::file_size(curve_file)),
                        elapsed);
    last_checkpoint = Clock::now();
  };
  auto last_print = started;
  const auto on_progress = [&](const GeneralistProgress& p) {
    WriteCurveRow(curve, p);
    const auto now = Clock::now();
    if (!p.validation && now - last_print < std::chrono::seconds(5))
      return;
    last_print = now;
    PrintProgress(p, job.steps, std::chrono::duration<double>(now - started).count());
  };
  const Scenario& settings = job.source.settings;
  const GeneralistResult r = TrainGeneralist(*job.source.draw, agent, settings.agent, g,
                                             FirstEpisodeRun(settings), on_progress, checkpoints);
  seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return r;
}

nlohmann::json ResultJson(const GeneralistJob& job, const GeneralistResult& r, double seconds) {
  const Scenario& settings = job.source.settings;
  nlohmann::json result = {{"general", true},
                           {"algorithm", settings.agent.algorithm},
                           {"action_space", settings.env.action_space},
                           {"fidelity", settings.env.fidelity},
                           {"seed", settings.agent.seed},
                           {"training", job.source.description},
                           {"steps", r.steps},
                           {"episodes", r.episodes},
                           {"kept_at_steps", r.kept_at_steps},
                           {"validation_ratio", r.best_validation},
                           {"validation", ValidationJson(r.validation)},
                           {"train_seconds", seconds},
                           // The commit and the libraries it was trained with.
                           {"build", DescribeBuild(ThisBuild())}};
  result["training"]["seed"] = settings.agent.seed;
  if (job.source.draw->Generated()) {
    const std::uint64_t first = job.source.draw->FirstTrainingSeed();
    result["training"]["generator_seeds"] = {first + r.first_draw, first + r.last_draw};
    result["training"]["validation_seeds"] = {
        kValidationSeedBase,
        kValidationSeedBase + static_cast<std::uint64_t>(job.validation_scenarios) - 1};
  }
  // The replay's runs: a general policy is flown greedy from the baseline with run 1.
  result.update(SeedStreamJson(FirstEpisodeRun(settings), 1));
  result["general"] = true;
  return result;
}

void PrintSummary(const GeneralistJob& job, const GeneralistResult& r, double seconds,
                  const nlohmann::json& result) {
  if (job.t.json) {
    std::cout << result.dump(2) << std::endl;
    return;
  }
  std::printf(
      "trained a policy for any scenario (ppo, seed %llu): %lld steps, %lld episodes "
      "in %s; %.3f of the oracle's reward on %zu validation scenarios\npolicy in %s\n",
      static_cast<unsigned long long>(job.source.settings.agent.seed),
      static_cast<long long>(r.steps), static_cast<long long>(r.episodes),
      FormatDuration(seconds).c_str(), r.best_validation, r.validation.size(), job.t.out.c_str());
}

// Trains, then writes the policy folder in OUT.partial and renames it to OUT.
void TrainAndWritePolicy(const GeneralistJob& job) {
  const Scenario& settings = job.source.settings;
  UavPositioningEnv example(settings);
  PpoAgent agent(settings.agent, static_cast<int>(example.ObservationSpace().Dim()),
                 example.ActionSpace().n, job.steps, example.UeSlots());
  double seconds = 0.0;
  const GeneralistResult r = TrainInPartial(job, agent, seconds);
  agent.Save(job.partial.string());
  const nlohmann::json result = ResultJson(job, r, seconds);
  std::ofstream(job.partial / "result.json") << result.dump(2) << '\n';
  std::ofstream(job.partial / "scenario.json") << ToJson(settings).dump(2) << '\n';
  job.checkpoint.Remove();
  fs::rename(job.partial, job.t.out);
  PrintSummary(job, r, seconds, result);
}

}  // namespace

bool TrainsAcrossScenarios(const TrainOptions& t) {
  return !t.generated.empty() || !t.scenarios_dir.empty();
}

int GeneralistTrainCommand(const CommonOptions& options, const TrainOptions& t) {
  CheckGeneralistOptions(options, t);
  const long long steps = *t.steps;
  const int validation_scenarios =
      t.validation_scenarios.value_or(GeneralistOptions{}.validation_scenarios);
  const Source source = t.generated.empty() ? FolderSource(t, options.overrides)
                                            : GeneratedSource(t, options.overrides);
  if (fs::exists(fs::path(t.out)))
    throw ConfigError("--out", t.out + " already exists; choose another folder or remove it");
  const fs::path partial = t.out + ".partial";
  const GeneralistCheckpoint checkpoint(partial,
                                        TrainingFingerprint(source, steps, validation_scenarios));
  const std::optional<SavedCheckpoint> resumed = checkpoint.Find();
  if (!resumed)
    CreatePartial(partial);
  try {
    TrainAndWritePolicy({t, steps, validation_scenarios, source, partial, checkpoint, resumed});
  } catch (...) {
    std::error_code ec;
    if (!checkpoint.Exists())  // a checkpoint stays, for the same command to go on from
      fs::remove_all(partial, ec);
    throw;
  }
  return kExitOk;
}

}  // namespace rlpos::sim
