#include "common/scenario/scenario_contradiction.h"

#include <utility>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

using json = nlohmann::json;

// The fields a document keeps as its own (the header says why): {object, key}, "" the top.
const std::vector<std::pair<std::string, std::string>>& DocumentsOwn() {
  static const std::vector<std::pair<std::string, std::string>> own{
      {"", "name"},       {"", "description"}, {"", "log_level"},
      {"", "simulation"}, {"env", "fidelity"}, {"", "agent"}};
  return own;
}

// The top-level keys in the order a reader thinks of a scenario: the place, who is in it, how
// the agent moves, how they talk. Keys not listed (none today) are compared after them.
const std::vector<std::string>& ReadingOrder() {
  static const std::vector<std::string> order{"venue", "buildings", "ues",     "uavs",
                                              "env",   "wifi",      "traffic", "propagation"};
  return order;
}

// The scenario's JSON with the same keys whatever form it was written in: every UAV under
// "uavs" with its channel, env.turn_steps, observed_ues and height_map written out, the document's
// own fields dropped. A UAV's name is a label (a listed UAV's default differs from a single one's):
// the UEs' "uav" fields, compared, say which UAV serves whom.
json Comparable(const Scenario& s) {
  json d = ToJson(s);
  for (const auto& [object, key] : DocumentsOwn()) {
    json& parent = object.empty() ? d : d[object];
    parent.erase(key);
  }
  json uavs = d.contains("uavs") ? d["uavs"] : json::array({d["uav"]});
  for (std::size_t i = 0; i < uavs.size() && i < s.uavs.size(); ++i) {
    uavs[i].erase("name");
    uavs[i]["channel"] = s.uavs[i].channel;
  }
  d.erase("uav");
  d["uavs"] = uavs;
  d["env"]["turn_steps"] = s.env.turn_steps;
  d["env"]["observed_ues"] = s.env.observed_ues;
  d["env"]["height_map"] = s.env.height_map;
  d["env"]["coverage_map"] = s.env.coverage_map;
  d["env"]["coverage_refine"] = s.env.coverage_refine;
  return d;
}

// A value as the one-line message shows it: its JSON, cut short when long.
std::string Shown(const json& v) {
  std::string text = v.dump();
  constexpr std::size_t kMax = 60;
  if (text.size() > kMax)
    text = text.substr(0, kMax - 3) + "...";
  return text;
}

Contradiction Differs(const std::string& path, const std::string& here, const std::string& there) {
  return {path.empty() ? "/" : path, here + " in the scenario, " + there + " in the policy"};
}

std::optional<Contradiction> FirstDifference(const json& here, const json& policy,
                                             const std::string& path) {
  if (here == policy)
    return std::nullopt;
  if (here.is_object() && policy.is_object()) {
    for (const auto& [key, value] : policy.items()) {
      if (!here.contains(key))
        return Differs(path + "/" + key, "absent", Shown(value));
      if (auto d = FirstDifference(here[key], value, path + "/" + key))
        return d;
    }
    for (const auto& [key, value] : here.items()) {
      if (!policy.contains(key))
        return Differs(path + "/" + key, Shown(value), "absent");
    }
  }
  if (here.is_array() && policy.is_array()) {
    if (here.size() != policy.size()) {
      return Differs(path, std::to_string(here.size()) + " entries", std::to_string(policy.size()));
    }
    for (std::size_t i = 0; i < here.size(); ++i) {
      if (auto d = FirstDifference(here[i], policy[i], path + "/" + std::to_string(i)))
        return d;
    }
  }
  return Differs(path, Shown(here), Shown(policy));
}

// The trained scenario's document with `stated` on top (JSON merge patch: objects merge,
// anything else is replaced). The UAVs are always the document's own, its default one if it
// states none: they are what gets placed, and scored, in the caller's scenario.
json Overlay(const Scenario& trained, const json& stated) {
  json merged = ToJson(trained);
  merged.erase("uav");
  merged.erase("uavs");
  merged.merge_patch(stated);
  // The agent is the policy's and is not compared; the parser only asks for one that fits the
  // action space.
  const json& env = merged["env"];
  const bool continuous = env.is_object() && env.value("action_space", "") == "continuous";
  merged["agent"] = {{"algorithm", continuous ? "sac" : "dqn"}};
  return merged;
}

}  // namespace

std::optional<Contradiction> FirstContradiction(const Scenario& trained, const json& stated) {
  Scenario overlaid;
  try {
    overlaid = ParseScenario(Overlay(trained, stated));
  } catch (const ConfigError& e) {
    // The document's fields do not even fit with the trained scenario's (a smaller venue than
    // its buildings, say).
    return Contradiction{e.path(), e.problem() + " (the scenario's fields on the policy's)"};
  }
  const json here = Comparable(overlaid);
  const json policy = Comparable(trained);
  std::optional<Contradiction> found;
  for (const auto& key : ReadingOrder()) {
    found = FirstDifference(here.value(key, json()), policy.value(key, json()), "/" + key);
    if (found)
      break;
  }
  if (!found)
    found = FirstDifference(here, policy, "");
  // Named as the document names it: a single UAV is "/uav".
  const std::string first = "/uavs/0";
  if (found && !overlaid.uavs_listed && found->path.rfind(first, 0) == 0)
    found->path = "/uav" + found->path.substr(first.size());
  return found;
}

}  // namespace rlpos
