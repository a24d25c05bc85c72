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
#include "common/wire/policy_bundle.h"

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

// An rl positioner that names a policy folder instead of training one:
// {"rl": {"policy": "policies/p1", "name": "p1"}} in "positioners" (or in "track"'s, a policy
// for any scenario flown online). Its evals and track runs are labelled PolicyLabel(name); the
// folder travels packed, as its bundle.
struct CampaignPolicy {
  std::string folder;    // as written in the campaign
  std::string name;      // "name", or the folder's last component
  PolicyBundle bundle;   // its files and their sha256
  bool placed = true;    // listed in "positioners": a position job and its evals
  bool tracked = false;  // listed in "track"'s positioners: track runs that fly it online
};

// "rl+<name>": a named policy's eval label, apart from trained rl's "rl" and "rl@...".
std::string PolicyLabel(const std::string& name);

// A campaign file's "train" section (rlpos-sim train's own command line is sim::TrainOptions;
// a scenario's keys are its sections' *Settings).
struct CampaignTrainSection {
  std::vector<std::uint64_t> seeds{1};  // the first seed gives the plain "rl"/"offsetK" labels
  std::string fidelity = "analytic";    // analytic | packet
  std::optional<int> episodes;  // agent.train_episodes of the train jobs; unset: the scenario's
  // Each trains its own policies, labelled "rl@<algorithm>" (and "offsetK@<algorithm>"), in
  // AllAlgorithms() order. Empty: the scenario's agent.algorithm, with the plain labels.
  std::vector<std::string> algorithms;
};

struct CampaignEvalSection {
  std::optional<double> duration;  // s; unset: the scenario's simulation.duration
  std::optional<double> warmup;    // s; unset: the scenario's simulation.warmup
};

// Limits a track section's runs: a run's intervals travel back in its result, whose size the
// wire bounds (wire::kMaxResultJson).
constexpr int kMaxTrackIntervals = 600;

// Runs in which the UEs walk and the UAVs follow (rlpos-sim track): one job per scenario,
// positioner and RngRun. "track": {"positioners": [...], "duration": D, "fidelity": F}.
struct CampaignTrackSection {
  // Held (baseline, centroid, oracle) and tracking (oracle-track, centroid-track) ones, in
  // TrackPositionerNames() order; named policies are CampaignSpec::policies marked tracked.
  // Neither: no track section, no track jobs.
  std::vector<std::string> positioners;
  double duration = 0.0;  // s of each run
  std::string fidelity = "analytic";
};

// The positioners a campaign's track section may select, in canonical order.
const std::vector<std::string>& TrackPositionerNames();

struct CampaignSpec {
  std::string name;
  std::vector<CampaignScenario> scenarios;
  std::vector<std::uint64_t> rng_runs;   // sorted, unique
  std::vector<std::string> positioners;  // canonical order, unique
  std::vector<CampaignPolicy> policies;  // named policies, as listed ("positioners", "track")
  CampaignTrainSection train;
  CampaignEvalSection eval;
  CampaignTrackSection track;
  int retries = 2;               // extra attempts after the first
  double job_timeout_s = 600.0;  // a running job older than this is failed

  bool Uses(const std::string& positioner) const;
  // True when the campaign has a track section (track positioners or tracked policies).
  bool Tracks() const;
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

// Where a campaign's named policies come from: given the folder as the campaign writes it and
// the JSON path to blame, returns its bundle. Throws ConfigError.
using PolicySource =
    std::function<PolicyBundle(const std::string& folder, const std::string& where)>;
// Folders relative to `base_dir`, read and packed (wire/policy_bundle_files.h).
PolicySource FilePolicySource(const std::string& base_dir);
// Bundles sent with the campaign, by folder name. The map must outlive the source.
PolicySource SentPolicySource(const std::map<std::string, PolicyBundle>& bundles);

// `base_dir` is the folder scenario paths and policy folders are relative to. A named policy
// is checked where it is cheap: its files (a fixed list, bounded), its scenario.json parsed,
// and no campaign scenario contradicting it (scenario/scenario_contradiction.h). Throws
// ConfigError. Without a policy source, a named policy is refused.
CampaignSpec ParseCampaign(const nlohmann::json& document, const std::string& base_dir);
CampaignSpec ParseCampaign(const nlohmann::json& document, const ScenarioSource& source,
                           const PolicySource& policies = nullptr);

// Reads a campaign file; scenario paths are relative to its folder. Throws ConfigError; like
// ReadJsonFile, errors about the file itself have an empty path (callers prefix the file name).
CampaignSpec ReadCampaignFile(const std::string& file);

// The campaign's eval settings as overrides ("simulation.duration=D", "simulation.warmup=W"):
// what every job's scenario is validated with, after the scenario entry's own overrides.
std::vector<std::string> EvalOverrides(const CampaignEvalSection& eval);

// The canonical resolved campaign: every default explicit, runs and positioners sorted, each
// scenario's document included, no absolute path (so the campaign id does not depend on where
// the repository is checked out). This is what the campaign id hashes and the store keeps.
nlohmann::json ToJson(const CampaignSpec& spec);
// The document a scenario entry of ToJson's "scenarios" ({"file", "set", "document"}) states: its
// "document" with its "set" applied, what the entry's jobs run. An entry read back from a store
// may come from another build: throws ConfigError, at the entry's key, when "document" is not an
// object or "set" not a list of strings, and as ApplyOverrides does.
nlohmann::json StatedScenarioDocument(const nlohmann::json& entry);
// ToJson(spec).dump(), the canonical text, without the tree's transient cost (below).
std::string ToJsonText(const CampaignSpec& spec);

}  // namespace rlpos
