#include "common/campaign/campaign_policy.h"

#include <filesystem>
#include <optional>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/scenario/scenario_contradiction.h"
#include "common/scenario/scenario_parser.h"
#include "common/wire/general_policy.h"
#include "common/wire/identifiers.h"
#include "common/wire/policy_bundle_files.h"

namespace rlpos {
namespace {

using nlohmann::json;

// The document a campaign scenario's jobs state (its "set" applied): what a policy placed
// there must fit.
json StatedDocument(const CampaignScenario& s) {
  json stated = s.document;
  ApplyOverrides(stated, s.overrides);
  return stated;
}

// What a campaign checks of a policy folder: its scenario.json, and what its result.json says
// of a policy for any scenario.
struct PolicyFacts {
  Scenario trained;
  GeneralPolicyScope scope;
};

// The cheap parts of what `position --policy` reads.
PolicyFacts CheckPolicyFiles(const PolicyBundle& bundle, const std::string& folder,
                             const std::string& where) {
  PolicyFacts facts;
  Scenario& trained = facts.trained;
  for (const auto& f : bundle.files) {
    if (f.name.size() < 5 || f.name.compare(f.name.size() - 5, 5, ".json") != 0)
      continue;
    json document;
    try {
      document = json::parse(f.data);
    } catch (const json::exception&) {
      throw ConfigError(where, "policy folder \"" + folder + "\": " + f.name + " is not JSON");
    }
    if (!document.is_object()) {
      throw ConfigError(where, "policy folder \"" + folder + "\": " + f.name +
                                   ": /: expected an object, got " + TypeName(document));
    }
    if (f.name == "policy.json" && document.value("format", json()) != "torchscript") {
      throw ConfigError(where, "policy folder \"" + folder +
                                   "\": policy.json: /format: expected \"torchscript\"");
    }
    if (f.name == "result.json") {
      try {
        facts.scope = ReadGeneralPolicyScope(document);
      } catch (const std::invalid_argument& e) {
        throw ConfigError(where, "policy folder \"" + folder + "\": result.json: " + e.what());
      }
    }
    if (f.name != "scenario.json")
      continue;
    try {
      trained = ParseScenario(document);
    } catch (const ConfigError& e) {
      throw ConfigError(where, "policy folder \"" + folder + "\": scenario.json: " + e.describe());
    }
  }
  return facts;
}

// A policy for any scenario flies in the campaign's scenario with its own env and agent: the
// scenario may restate them, not change them, and must have a UAV count it was trained for.
// `own_interval`: the scenario keeps its env.decision_interval (a track run asks the policy
// that often).
std::optional<Contradiction> GeneralMisfit(const PolicyFacts& facts, const CampaignScenario& s,
                                           bool own_interval = false) {
  json stated = StatedDocument(s);
  Scenario target = ParseScenario(stated);
  if (own_interval && stated.contains("env") && stated["env"].is_object())
    stated["env"].erase("decision_interval");
  const int uavs = static_cast<int>(target.uavs.size());
  if (uavs < facts.scope.min_uavs || uavs > facts.scope.max_uavs) {
    return Contradiction{"/uavs", std::to_string(uavs) + " UAVs in the scenario, " +
                                      std::to_string(facts.scope.min_uavs) + "-" +
                                      std::to_string(facts.scope.max_uavs) + " in the policy"};
  }
  target.env = facts.trained.env;
  target.agent = facts.trained.agent;
  return FirstContradiction(target, stated);
}

CampaignPolicy ReadPolicyEntry(const json& v, const std::string& path, const PolicySource& source,
                               const std::vector<CampaignScenario>& scenarios,
                               bool tracked = false) {
  ObjectReader outer(v, path);
  const json* rl = outer.Child("rl");
  outer.Finish();  // an unknown key, misspelt "rl" included, is named here
  if (!rl)
    throw ConfigError(path, "expected {\"rl\": {\"policy\": \"FOLDER\"}}");
  const std::string rl_path = outer.PathOf("rl");
  ObjectReader r(*rl, rl_path);
  if (!r.Has("policy")) {
    r.Finish();
    throw ConfigError(r.PathOf("policy"), "is required (the policy folder)");
  }
  CampaignPolicy policy;
  policy.folder = r.String("policy", "");
  const std::string where = r.PathOf("policy");
  if (policy.folder.empty())
    throw ConfigError(where, "the folder name is empty");
  std::string last = std::filesystem::path(policy.folder).lexically_normal().filename().string();
  if (last.empty())  // "policies/p1/"
    last =
        std::filesystem::path(policy.folder).lexically_normal().parent_path().filename().string();
  policy.name = r.String("name", last);
  const std::string name_where = r.Has("name") ? r.PathOf("name") : where;
  r.Finish();
  if (!wire::IsSafeName(policy.name, 64)) {
    throw ConfigError(name_where, "policy name \"" + wire::Printable(policy.name) +
                                      "\" must be 1-64 of [A-Za-z0-9._@+-]; give one with "
                                      "\"name\"");
  }
  if (!source)
    throw ConfigError(where, "a named policy cannot be read here");
  policy.bundle = source(policy.folder, where);
  const PolicyFacts facts = CheckPolicyFiles(policy.bundle, policy.folder, where);
  const Scenario& trained = facts.trained;
  if (tracked && (!facts.scope.general || policy.bundle.format != PolicyFormat::kTrained)) {
    throw ConfigError(where, "policy \"" + policy.folder +
                                 "\" is not a policy for any scenario of the trained format "
                                 "(rlpos-sim train --generated): a track run flies it in the "
                                 "scenario of each moment");
  }
  policy.placed = !tracked;
  policy.tracked = tracked;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const CampaignScenario& s = scenarios[i];
    const auto c = facts.scope.general ? GeneralMisfit(facts, s, tracked)
                                       : FirstContradiction(trained, StatedDocument(s));
    if (c) {
      throw ConfigError(where, "policy \"" + policy.folder + "\" (trained on " + trained.name +
                                   ") does not fit /scenarios/" + std::to_string(i) + " (" +
                                   s.file + "): " + c->path + ": " + c->problem);
    }
  }
  return policy;
}

}  // namespace

std::vector<CampaignPolicy> ReadPolicies(const json& v, const std::string& path,
                                         const PolicySource& source,
                                         const std::vector<CampaignScenario>& scenarios) {
  std::vector<CampaignPolicy> policies;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_object())
      continue;
    const std::string item_path = JoinPath(path, i);
    if (policies.size() == kMaxCampaignPolicies) {
      throw ConfigError(item_path,
                        "more than " + std::to_string(kMaxCampaignPolicies) + " named policies");
    }
    CampaignPolicy policy = ReadPolicyEntry(v[i], item_path, source, scenarios);
    for (const auto& other : policies) {
      if (other.name == policy.name) {
        throw ConfigError(item_path, "policy name \"" + policy.name +
                                         "\" is already used; give another with \"name\"");
      }
    }
    policies.push_back(std::move(policy));
  }
  return policies;
}

void ReadTrackPolicies(const json& v, const std::string& path, const PolicySource& source,
                       const std::vector<CampaignScenario>& scenarios,
                       std::vector<CampaignPolicy>& policies) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_object())
      continue;
    const std::string item_path = JoinPath(path, i);
    CampaignPolicy policy = ReadPolicyEntry(v[i], item_path, source, scenarios, true);
    bool merged = false;
    for (auto& other : policies) {
      if (other.name != policy.name)
        continue;
      if (other.tracked || other.bundle.sha256 != policy.bundle.sha256) {
        throw ConfigError(item_path, "policy name \"" + policy.name +
                                         "\" is already used; give another with \"name\"");
      }
      other.tracked = merged = true;
    }
    if (merged)
      continue;
    if (policies.size() == kMaxCampaignPolicies) {
      throw ConfigError(item_path,
                        "more than " + std::to_string(kMaxCampaignPolicies) + " named policies");
    }
    policies.push_back(std::move(policy));
  }
}

std::string PolicyLabel(const std::string& name) {
  return "rl+" + name;
}

PolicySource FilePolicySource(const std::string& base_dir) {
  return [base_dir](const std::string& folder, const std::string& where) {
    const std::filesystem::path dir(folder);
    const std::string path = (dir.is_absolute() ? dir : std::filesystem::absolute(base_dir / dir))
                                 .lexically_normal()
                                 .string();
    try {
      return ReadPolicyBundle(path);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(where, e.what());
    }
  };
}

PolicySource SentPolicySource(const std::map<std::string, PolicyBundle>& bundles) {
  return [&bundles](const std::string& folder, const std::string& where) {
    const auto it = bundles.find(folder);
    if (it == bundles.end())
      throw ConfigError(where, "policy \"" + folder + "\" was not sent with the campaign");
    return it->second;
  };
}

}  // namespace rlpos
