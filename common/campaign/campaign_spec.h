#pragma once
// The campaign model: which scenarios, runs and positioners to evaluate, and how. Parsed from a
// campaign JSON with every field validated (ConfigError naming the JSON path); each scenario is
// parsed and validated too, so a campaign never reaches the workers with a broken scenario.
#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// The positioners a campaign may select, in canonical (report) order. "offsets" are the paper's
// positions 1-5 around the RL position; "rl" is the trained agent's final greedy position.
const std::vector<std::string>& AllPositioners();

struct CampaignScenario {
  std::string file;                    // as written in the campaign
  std::string path;                    // where it was read from (messages only)
  std::vector<std::string> overrides;  // "set": every job's overrides of the document, in order
  nlohmann::json document;             // the scenario file as read (before overrides)
  Scenario scenario;                   // parsed with the eval settings and overrides applied
};

struct TrainSettings {
  std::vector<std::uint64_t> seeds{1};  // the first seed gives the plain "rl"/"offsetK" labels
  std::string fidelity = "analytic";    // analytic | packet
  std::optional<int> episodes;  // agent.train_episodes of the train jobs; unset: the scenario's
  // Each trains its own policies, labelled "rl@<algorithm>" (and "offsetK@<algorithm>"), in
  // AllAlgorithms() order. Empty: the scenario's agent.algorithm, with the plain labels.
  std::vector<std::string> algorithms;
};

struct EvalSettings {
  std::optional<double> duration;  // s; unset: the scenario's simulation.duration
  std::optional<double> warmup;    // s; unset: the scenario's simulation.warmup
};

struct CampaignSpec {
  std::string name;
  std::vector<CampaignScenario> scenarios;
  std::vector<std::uint64_t> rng_runs;   // sorted, unique
  std::vector<std::string> positioners;  // canonical order, unique
  TrainSettings train;
  EvalSettings eval;
  int retries = 2;               // extra attempts after the first
  double job_timeout_s = 600.0;  // a running job older than this is failed

  bool Uses(const std::string& positioner) const;
  // True when train jobs are needed ("rl" or "offsets" selected).
  bool NeedsTraining() const;
};

// Where a campaign's scenario documents come from: given the file name as the campaign writes it
// and the JSON path to blame, returns the document and sets `path` to where it came from.
// Throws ConfigError.
using ScenarioSource = std::function<nlohmann::json(const std::string& file,
                                                    const std::string& where, std::string& path)>;
// Files relative to `base_dir`.
ScenarioSource FileScenarioSource(const std::string& base_dir);
// Documents sent with the campaign, by file name (the coordinator never opens a path it was
// sent). The map must outlive the source.
ScenarioSource SentScenarioSource(const std::map<std::string, nlohmann::json>& documents);

// `base_dir` is the folder scenario paths are relative to. Throws ConfigError.
CampaignSpec ParseCampaign(const nlohmann::json& document, const std::string& base_dir);
CampaignSpec ParseCampaign(const nlohmann::json& document, const ScenarioSource& source);

// Reads a campaign file; scenario paths are relative to its folder. Throws ConfigError; like
// ReadJsonFile, errors about the file itself have an empty path (callers prefix the file name).
CampaignSpec ReadCampaignFile(const std::string& file);

// The campaign's eval settings as overrides ("simulation.duration=D", "simulation.warmup=W"):
// what every job's scenario is validated with, after the scenario entry's own overrides.
std::vector<std::string> EvalOverrides(const EvalSettings& eval);

// The canonical resolved campaign: every default explicit, runs and positioners sorted, each
// scenario's document included, no absolute path (so the campaign id does not depend on where
// the repository is checked out). This is what the campaign id hashes and the store keeps.
nlohmann::json ToJson(const CampaignSpec& spec);
// ToJson(spec).dump(), the canonical text, without the tree's transient cost (below).
std::string ToJsonText(const CampaignSpec& spec);

}  // namespace rlpos
