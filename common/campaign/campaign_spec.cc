#include "common/campaign/campaign_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "common/campaign/campaign_policy.h"
#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "common/config/did_you_mean.h"
#include "common/config/object_reader.h"
#include "common/scenario/names.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "common/wire/identifiers.h"
#include "common/wire/job_order.h"
#include "common/wire/limits.h"

namespace rlpos {
namespace {

using nlohmann::json;

// Far more runs than any study needs; a typo such as [1, 3000000] fails here, not in the DB.
constexpr std::uint64_t kMaxRngRuns = 100000;

std::uint64_t ReadUnsigned(const json& v, const std::string& path, std::uint64_t max) {
  if (!v.is_number_integer()) {
    throw ConfigError(path, "expected a non-negative integer, got " +
                                (v.is_number() ? std::string("a fractional number") : TypeName(v)));
  }
  if (v.is_number_unsigned()) {
    const auto x = v.get<std::uint64_t>();
    if (x <= max)
      return x;
    throw ConfigError(path, "must be <= " + std::to_string(max) + ", got " + std::to_string(x));
  }
  const auto x = v.get<long long>();
  if (x < 0)
    throw ConfigError(path, "must not be negative, got " + std::to_string(x));
  return static_cast<std::uint64_t>(x);
}

// A missing required key may just be misspelt: say so rather than only "is required".
[[noreturn]] void MissingKey(const json& object, const std::string& parent, const std::string& key,
                             const std::vector<std::string>& known, const std::string& hint) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end())
      continue;
    if (!ClosestMatch(it.key(), {key}).empty()) {
      throw ConfigError(JoinPath(parent, it.key()),
                        "unknown key \"" + it.key() + "\"; did you mean \"" + key + "\"?");
    }
  }
  throw ConfigError(JoinPath(parent, key), "is required" + hint);
}

const std::vector<std::string> kCampaignKeys{"name",        "scenarios", "rng_runs",
                                             "positioners", "train",     "eval",
                                             "track",       "retries",   "job_timeout_s"};

const json& NonEmptyArray(const json& v, const std::string& path) {
  if (!v.is_array() || v.empty()) {
    throw ConfigError(path, "expected a non-empty array, got " +
                                (v.is_array() ? std::string("an empty array") : TypeName(v)));
  }
  return v;
}

// A sorted list of unique integers, rejecting duplicates (a duplicate is always a mistake here).
std::vector<std::uint64_t> ReadUniqueList(const json& v, const std::string& path, std::uint64_t max,
                                          bool sort) {
  std::vector<std::uint64_t> out;
  for (std::size_t i = 0; i < NonEmptyArray(v, path).size(); ++i) {
    const std::uint64_t x = ReadUnsigned(v[i], JoinPath(path, i), max);
    if (std::find(out.begin(), out.end(), x) != out.end()) {
      throw ConfigError(JoinPath(path, i), std::to_string(x) + " is listed twice");
    }
    out.push_back(x);
  }
  if (sort)
    std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint64_t> ReadRngRuns(const json& v, const std::string& path) {
  if (v.is_object()) {
    ObjectReader r(v, path);
    const json* list = r.Child("list");
    if (!list)
      MissingKey(v, path, "list", {}, " ({\"list\": [1, 2, 5]})");
    auto runs = ReadUniqueList(*list, r.PathOf("list"), UINT64_MAX, true);
    r.Finish();
    if (runs.size() > kMaxRngRuns) {
      throw ConfigError(r.PathOf("list"), "more than " + std::to_string(kMaxRngRuns) + " runs");
    }
    return runs;
  }
  if (!v.is_array() || v.size() != 2) {
    // [1] is a list of one run to some: say what a pair is, and how many there were.
    const std::string got = v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v);
    throw ConfigError(path, "expected [first, last] (2 numbers) or {\"list\": [...]}, got " + got);
  }
  const std::uint64_t first = ReadUnsigned(v[0], JoinPath(path, 0), UINT64_MAX);
  const std::uint64_t last = ReadUnsigned(v[1], JoinPath(path, 1), UINT64_MAX);
  if (last < first)
    throw ConfigError(path, "first must not be above last");
  if (last - first >= kMaxRngRuns) {
    throw ConfigError(path, "more than " + std::to_string(kMaxRngRuns) + " runs");
  }
  std::vector<std::uint64_t> runs;
  for (std::uint64_t r = first; r <= last; ++r)
    runs.push_back(r);
  return runs;
}

// A non-empty list of distinct names among `all` (`what` names one in messages), returned in
// the order of `all`: the listing order changes no job, so it must not change the campaign id.
// `skip_objects`: objects in the list are the caller's (named policies), not names.
std::vector<std::string> ReadCanonicalList(const json& v, const std::string& path,
                                           const std::vector<std::string>& all,
                                           const std::string& what, bool skip_objects = false) {
  std::vector<std::string> chosen;
  for (std::size_t i = 0; i < NonEmptyArray(v, path).size(); ++i) {
    const std::string item_path = JoinPath(path, i);
    if (skip_objects && v[i].is_object())
      continue;
    if (!v[i].is_string())
      throw ConfigError(item_path, "expected a string, got " + TypeName(v[i]));
    const std::string name = v[i].get<std::string>();
    if (std::find(all.begin(), all.end(), name) == all.end()) {
      std::string list;
      for (const auto& a : all)
        list += (list.empty() ? "" : ", ") + a;
      std::string message = "unknown " + what + " \"" + name + "\" (one of: " + list + ")";
      const std::string hint = ClosestMatch(name, all);
      if (!hint.empty())
        message += "; did you mean \"" + hint + "\"?";
      throw ConfigError(item_path, message);
    }
    if (std::find(chosen.begin(), chosen.end(), name) != chosen.end()) {
      throw ConfigError(item_path, "\"" + name + "\" is listed twice");
    }
    chosen.push_back(name);
  }
  std::vector<std::string> ordered;
  for (const auto& a : all) {
    if (std::find(chosen.begin(), chosen.end(), a) != chosen.end())
      ordered.push_back(a);
  }
  return ordered;
}

CampaignTrainSection ReadTrain(const json& v) {
  ObjectReader r(v, "/train");
  CampaignTrainSection train;
  if (const json* seeds = r.Child("seeds")) {
    // Not sorted: the first seed is the one whose evals get the plain "rl" labels.
    train.seeds = ReadUniqueList(*seeds, r.PathOf("seeds"), UINT32_MAX, false);
  }
  train.fidelity = r.String("fidelity", train.fidelity, NameList(kFidelities));
  if (r.Has("episodes"))
    train.episodes = static_cast<int>(r.Integer("episodes", 0, 1, 1000000));
  if (const json* algorithms = r.Child("algorithms")) {
    train.algorithms =
        ReadCanonicalList(*algorithms, r.PathOf("algorithms"), AllAlgorithms(), "algorithm");
  }
  r.Finish();
  return train;
}

CampaignEvalSection ReadEval(const json& v) {
  ObjectReader r(v, "/eval");
  CampaignEvalSection eval;
  if (r.Has("duration"))
    eval.duration = r.Number("duration", 0, Positive());
  if (r.Has("warmup"))
    eval.warmup = r.Number("warmup", 0, NonNegative());
  r.Finish();
  if (eval.duration && eval.warmup && *eval.warmup >= *eval.duration) {
    throw ConfigError("/eval/warmup", "must be shorter than the duration");
  }
  return eval;
}

CampaignTrackSection ReadTrack(const json& v) {
  ObjectReader r(v, "/track");
  CampaignTrackSection track;
  const json* positioners = r.Child("positioners");
  if (!positioners)
    throw ConfigError("/track/positioners", "is required (for example [\"oracle-track\"])");
  for (std::size_t i = 0; i < positioners->size() && positioners->is_array(); ++i) {
    if ((*positioners)[i] == "rl") {
      throw ConfigError(JoinPath("/track/positioners", i),
                        "rl in a track section flies a policy for any scenario: "
                        "{\"rl\": {\"policy\": \"FOLDER\"}}");
    }
  }
  // Named policies ({"rl": {...}}) are read with the scenarios (ReadTrackPolicies).
  track.positioners = ReadCanonicalList(*positioners, "/track/positioners", TrackPositionerNames(),
                                        "track positioner", true);
  if (!r.Has("duration"))
    throw ConfigError("/track/duration", "is required (s of each run)");
  track.duration = r.Number("duration", 0, Positive());
  if (track.duration > 86400)
    throw ConfigError("/track/duration", "must be at most 86400 s");
  track.fidelity = r.String("fidelity", track.fidelity, NameList(kFidelities));
  r.Finish();
  return track;
}

// The track runs of `entry` fit: at least one interval, one scored at packet level, and not
// more than the wire carries back.
void CheckTrackFits(const CampaignTrackSection& track, const CampaignScenario& entry,
                    const std::string& path) {
  const Scenario& s = entry.scenario;
  const double interval = s.env.decision_interval;
  const double count = std::floor(track.duration / interval + 1e-9);
  const std::string of = "scenario \"" + s.name + "\" (" + path + ", env.decision_interval " +
                         FormatNumber(interval) + " s)";
  if (count < 1)
    throw ConfigError("/track/duration", "is shorter than one interval of " + of);
  if (count > kMaxTrackIntervals) {
    throw ConfigError("/track/duration",
                      "makes " + FormatNumber(count) + " intervals in " + of + ", more than " +
                          std::to_string(kMaxTrackIntervals) +
                          "; lengthen its env.decision_interval (\"set\") or shorten the runs");
  }
  if (track.fidelity == "packet" && (count - 1) * interval < s.simulation.warmup) {
    throw ConfigError("/track/duration", "leaves no interval after simulation.warmup (" +
                                             FormatNumber(s.simulation.warmup) + " s) in " + of);
  }
}

CampaignScenario ReadScenarioEntry(const json& v, const std::string& path,
                                   const ScenarioSource& source, const CampaignEvalSection& eval) {
  CampaignScenario entry;
  std::string file_path = path;  // where a problem with the file itself is reported
  std::string set_path;
  if (v.is_string()) {
    entry.file = v.get<std::string>();
  } else if (v.is_object()) {
    ObjectReader r(v, path);
    if (!r.Has("file"))
      MissingKey(v, path, "file", {"set"}, " (the scenario JSON)");
    entry.file = r.String("file", "");
    file_path = r.PathOf("file");
    if (const json* set = r.Child("set")) {
      set_path = r.PathOf("set");
      if (!set->is_array())
        throw ConfigError(set_path, "expected an array, got " + TypeName(*set));
      for (std::size_t i = 0; i < set->size(); ++i) {
        if (!(*set)[i].is_string()) {
          throw ConfigError(JoinPath(set_path, i),
                            "expected \"path=value\", got " + TypeName((*set)[i]));
        }
        entry.overrides.push_back((*set)[i].get<std::string>());
      }
    }
    r.Finish();
  } else {
    throw ConfigError(path, "expected a file name or {\"file\", \"set\"}, got " + TypeName(v));
  }
  if (entry.file.empty())
    throw ConfigError(file_path, "the file name is empty");

  entry.document = source(entry.file, file_path, entry.path);

  // Validate what the evals will run, in the order a job's scenario is made: the entry's own
  // overrides, then the campaign's eval settings (CheckJobSettings refuses an override that
  // gives one of those another value).
  json effective = entry.document;
  if (!effective.is_object()) {
    throw ConfigError(path, entry.file + ": /: expected an object, got " + TypeName(effective));
  }
  for (std::size_t i = 0; i < entry.overrides.size(); ++i) {
    try {
      // Overrides travel to the workers: they are held to what a worker accepts.
      CheckOverride(ParseOverride(entry.overrides[i]));
      ApplyOverrides(effective, {entry.overrides[i]});
    } catch (const ConfigError& e) {
      throw ConfigError(JoinPath(set_path, i), e.describe());
    } catch (const std::invalid_argument& e) {
      throw ConfigError(JoinPath(set_path, i), e.what());
    }
  }
  try {
    ApplyOverrides(effective, EvalOverrides(eval));
    entry.scenario = ParseScenario(effective);
  } catch (const ConfigError& e) {
    throw ConfigError(path, entry.file + ": " + e.describe());
  }
  if (!wire::IsSafeName(entry.scenario.name, wire::kMaxNameLength)) {
    // Job keys are "<kind>/<scenario>/..." and name the workers' folders.
    throw ConfigError(path, entry.file + ": scenario name \"" + entry.scenario.name +
                                "\" must be 1-128 of [A-Za-z0-9._@+-]");
  }
  return entry;
}

}  // namespace

const std::vector<std::string>& AllPositioners() {
  static const std::vector<std::string> all = NameList(kPositioners);
  return all;
}

const std::vector<std::string>& TrackPositionerNames() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> names = NameList(kPlacingPositioners);
    for (const std::string& name : NameList(kTrackingPositioners))
      names.push_back(name);
    return names;
  }();
  return all;
}

bool CampaignSpec::Tracks() const {
  if (!track.positioners.empty())
    return true;
  return std::any_of(policies.begin(), policies.end(),
                     [](const CampaignPolicy& p) { return p.tracked; });
}

bool CampaignSpec::Uses(const std::string& positioner) const {
  return std::find(positioners.begin(), positioners.end(), positioner) != positioners.end();
}

bool CampaignSpec::NeedsTraining() const {
  return Uses("rl") || Uses("offsets");
}

ScenarioSource FileScenarioSource(const std::string& base_dir) {
  return [base_dir](const std::string& file_name, const std::string& where, std::string& path) {
    const std::filesystem::path file(file_name);
    path = (file.is_absolute() ? file : std::filesystem::absolute(base_dir / file))
               .lexically_normal()
               .string();
    std::error_code status_error;
    if (!std::filesystem::is_regular_file(path, status_error)) {
      throw ConfigError(where, "scenario file \"" + path + "\" does not exist");
    }
    try {
      return ReadJsonFile(path);
    } catch (const ConfigError& e) {
      throw ConfigError(where, "scenario file \"" + path + "\": " + e.problem());
    }
  };
}

ScenarioSource SentScenarioSource(const std::map<std::string, json>& documents) {
  return [&documents](const std::string& file_name, const std::string& where, std::string& path) {
    const auto it = documents.find(file_name);
    if (it == documents.end()) {
      throw ConfigError(where, "scenario \"" + file_name + "\" was not sent with the campaign");
    }
    path = file_name;
    return it->second;
  };
}

CampaignSpec ParseCampaign(const json& document, const std::string& base_dir) {
  return ParseCampaign(document, FileScenarioSource(base_dir), FilePolicySource(base_dir));
}

CampaignSpec ParseCampaign(const json& document, const ScenarioSource& source,
                           const PolicySource& policies) {
  ObjectReader r(document, "");
  CampaignSpec spec;
  if (!r.Has("name"))
    MissingKey(document, "", "name", kCampaignKeys, "");
  spec.name = r.String("name", "");
  if (spec.name.empty())
    throw ConfigError("/name", "must not be empty");

  if (const json* train = r.Child("train"))
    spec.train = ReadTrain(*train);
  if (const json* eval = r.Child("eval"))
    spec.eval = ReadEval(*eval);
  const json* track = r.Child("track");
  if (track)
    spec.track = ReadTrack(*track);

  const json* scenarios = r.Child("scenarios");
  if (!scenarios) {
    MissingKey(document, "", "scenarios", kCampaignKeys, " (a list of scenario files)");
  }
  NonEmptyArray(*scenarios, "/scenarios");
  for (std::size_t i = 0; i < scenarios->size(); ++i) {
    const std::string path = JoinPath("/scenarios", i);
    CampaignScenario entry = ReadScenarioEntry((*scenarios)[i], path, source, spec.eval);
    for (std::size_t j = 0; j < spec.scenarios.size(); ++j) {
      if (spec.scenarios[j].scenario.name == entry.scenario.name) {
        throw ConfigError(path, "scenario name \"" + entry.scenario.name +
                                    "\" is already used by /scenarios/" + std::to_string(j) +
                                    "; rename one with \"set\": [\"name=...\"]");
      }
    }
    spec.scenarios.push_back(std::move(entry));
  }

  const json* runs = r.Child("rng_runs");
  if (!runs) {
    MissingKey(document, "", "rng_runs", kCampaignKeys, " ([first, last] or {\"list\": [...]})");
  }
  spec.rng_runs = ReadRngRuns(*runs, "/rng_runs");

  const json* positioners = r.Child("positioners");
  if (positioners && positioners->is_array() && positioners->empty() && track) {
    // [] with a track section: a campaign of track runs only.
  } else if (positioners) {
    spec.positioners =
        ReadCanonicalList(*positioners, "/positioners", AllPositioners(), "positioner", true);
    spec.policies = ReadPolicies(*positioners, "/positioners", policies, spec.scenarios);
  } else {
    spec.positioners = AllPositioners();
  }
  spec.retries = static_cast<int>(r.Integer("retries", spec.retries, 0, 100));
  spec.job_timeout_s = r.Number("job_timeout_s", spec.job_timeout_s, Positive());
  if (track)
    ReadTrackPolicies((*track)["positioners"], "/track/positioners", policies, spec.scenarios,
                      spec.policies);
  r.Finish();
  if (spec.Tracks()) {
    for (std::size_t i = 0; i < spec.scenarios.size(); ++i)
      CheckTrackFits(spec.track, spec.scenarios[i], JoinPath("/scenarios", i));
  }
  CheckJobSettings(spec);
  return spec;
}

CampaignSpec ReadCampaignFile(const std::string& file) {
  const json document = ReadJsonFile(file);
  const std::filesystem::path folder = std::filesystem::path(file).parent_path();
  return ParseCampaign(document, folder.empty() ? "." : folder.string());
}

std::vector<std::string> EvalOverrides(const CampaignEvalSection& eval) {
  std::vector<std::string> out;
  if (eval.duration)
    out.push_back("simulation.duration=" + FormatNumber(*eval.duration));
  if (eval.warmup)
    out.push_back("simulation.warmup=" + FormatNumber(*eval.warmup));
  return out;
}

json StatedScenarioDocument(const json& entry) {
  ObjectReader reader(entry, "");
  const json* document = reader.Child("document");
  if (!document || !document->is_object()) {
    throw ConfigError(reader.PathOf("document"),
                      "expected an object, got " + (document ? TypeName(*document) : "nothing"));
  }
  const json* set = reader.Child("set");
  if (!set || !set->is_array()) {
    throw ConfigError(reader.PathOf("set"),
                      "expected an array, got " + (set ? TypeName(*set) : "nothing"));
  }
  std::vector<std::string> overrides;
  for (std::size_t i = 0; i < set->size(); ++i) {
    if (!(*set)[i].is_string())
      throw ConfigError(JoinPath(reader.PathOf("set"), i), "expected a string");
    overrides.push_back((*set)[i].get<std::string>());
  }
  json stated = *document;
  ApplyOverrides(stated, overrides);
  return stated;
}

json ToJson(const CampaignSpec& spec) {
  json scenarios = json::array();
  for (const auto& s : spec.scenarios) {
    scenarios.push_back({{"file", s.file}, {"set", s.overrides}, {"document", s.document}});
  }
  json train = {
      {"seeds", spec.train.seeds}, {"fidelity", spec.train.fidelity}, {"episodes", nullptr}};
  if (spec.train.episodes)
    train["episodes"] = *spec.train.episodes;
  if (!spec.train.algorithms.empty())  // absent otherwise: older campaigns keep their ids
    train["algorithms"] = spec.train.algorithms;
  json eval = {{"duration", nullptr}, {"warmup", nullptr}};
  if (spec.eval.duration)
    eval["duration"] = *spec.eval.duration;
  if (spec.eval.warmup)
    eval["warmup"] = *spec.eval.warmup;
  json out = {{"name", spec.name},
              {"scenarios", scenarios},
              {"rng_runs", spec.rng_runs},
              {"positioners", spec.positioners},
              {"train", train},
              {"eval", eval},
              {"retries", spec.retries},
              {"job_timeout_s", spec.job_timeout_s}};
  if (spec.Tracks()) {  // absent otherwise: older campaigns keep their ids
    out["track"] = {{"positioners", spec.track.positioners},
                    {"duration", spec.track.duration},
                    {"fidelity", spec.track.fidelity}};
  }
  // Absent without named policies, so older campaigns keep their ids; with them, each one's
  // sha256 makes the same campaign with another policy another campaign.
  if (!spec.policies.empty()) {
    json policies = json::array();
    for (const auto& p : spec.policies) {
      json policy = {{"folder", p.folder},
                     {"name", p.name},
                     {"format", ToString(p.bundle.format)},
                     {"sha256", p.bundle.sha256}};
      if (p.tracked)  // the defaults absent: older campaigns keep their ids
        policy["track"] = true;
      if (!p.placed)
        policy["placed"] = false;
      policies.push_back(policy);
    }
    out["policies"] = policies;
  }
  return out;
}

std::string ToJsonText(const CampaignSpec& spec) {
  json tree = ToJson(spec);
  std::string text = tree.dump();
  // nlohmann's destructor first moves an array's elements to a growing stack of its own: for
  // 100k RngRuns that tripled the submit's peak memory. Numbers destroyed in place move nothing.
  tree["rng_runs"].get_ref<json::array_t&>().clear();
  return text;
}

}  // namespace rlpos
