#include "common/scenario/scenario_parser.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/default_sets.h"
#include "common/scenario/names.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_settings.h"

namespace rlpos {
namespace {

using nlohmann::json;

BuildingSpec ReadBuilding(const json& v, const std::string& path, std::size_t index) {
  BuildingSpec defaults;
  defaults.name = "building" + std::to_string(index);
  return ReadObject(v, path, BuildingSettings(), defaults);
}

UeSpec ReadUe(const json& v, const std::string& path, std::size_t index, const PhyProfile& phy) {
  UeSpec defaults;
  defaults.name = "ue" + std::to_string(index);
  UeSpec ue = ReadObject(v, path, UeSettings(), defaults);
  // A demand given as an MCS is that MCS's rate with the scenario's PHY.
  if (ue.demand_mcs >= 0) {
    const int max = MaxMcs(phy.standard);
    if (ue.demand_mcs > max) {
      throw ConfigError(path + "/demand/mcs", "must be in [0, " + std::to_string(max) + "], got " +
                                                  std::to_string(ue.demand_mcs));
    }
    ue.demand_mbps = McsDataRateMbps(phy, ue.demand_mcs);
  }
  return ue;
}

UavSpec ReadUav(const json& v, const Venue& venue, const std::string& path,
                const std::string& default_name) {
  UavSpec defaults;
  defaults.name = default_name;
  defaults.zone = {0, venue.width, 0, venue.depth, 1.0, venue.height};
  defaults.initial = {venue.width / 2, venue.depth / 2, 10.0};
  return ReadObject(v, path, UavSettings(), defaults);
}

EnvSpec ReadEnv(const json& v) {
  ObjectReader r(v, "/env");
  EnvSpec e;
  ReadSettings(r, EnvSettings(), e);
  e.reward = ReadSection(r.Child("reward"), RewardSettings());
  r.Finish();
  return e;
}

AgentSpec ReadAgent(const json& v, std::size_t uavs) {
  ObjectReader r(v, "/agent");
  AgentSpec a;
  ReadSettings(r, AgentNetworkSettings(), a);
  // The shared keys' defaults follow the algorithm and the number of UAVs.
  static_cast<AgentCommonSpec&>(a) = AgentCommonDefaults(a.algorithm, uavs);
  ReadSettings(r, DqnHyperparameters(), a.dqn);
  ReadSettings(r, AgentCommonHyperparameters(), static_cast<AgentCommonSpec&>(a));
  a.ppo = ReadSection(r.Child("ppo"), PpoHyperparameters());
  const json* sac = r.Child("sac");
  a.sac = ReadSection(sac, SacHyperparameters());
  // SAC's replay read DQN's agent.replay_capacity before it had its own: a SAC scenario that
  // sets only that one keeps its replay.
  if (a.algorithm == "sac" && r.Has("replay_capacity") &&
      !(sac && sac->contains("replay_capacity")))
    a.sac.replay_capacity = a.dqn.replay_capacity;
  r.Finish();
  return a;
}

// The UE encoder reads the "ues" slots, and only PPO's networks have one.
void CheckUeEncoder(const Scenario& s) {
  if (s.agent.ue_encoder.empty())
    return;
  if (s.agent.algorithm != "ppo") {
    throw ConfigError("/agent/ue_encoder",
                      "only ppo has a UE encoder, not " + s.agent.algorithm + "; remove it");
  }
  const auto& fields = s.env.observations;
  if (std::find(fields.begin(), fields.end(), "ues") == fields.end())
    throw ConfigError("/agent/ue_encoder", "needs \"ues\" in env.observations");
}

json AgentJson(const AgentSpec& a) {
  json agent = SettingsJson(a, AgentNetworkSettings());
  WriteSettings(a.dqn, DqnHyperparameters(), agent);
  WriteSettings<AgentCommonSpec>(a, AgentCommonHyperparameters(), agent);
  WriteSettings(a.ppo, PpoHyperparameters(), agent["ppo"]);
  WriteSettings(a.sac, SacHyperparameters(), agent["sac"]);
  return agent;
}

}  // namespace

json ParseJsonText(const std::string& text) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string what = e.what();
    const auto at = what.find("at line");
    throw ConfigError("", "malformed JSON " + (at == std::string::npos ? what : what.substr(at)));
  } catch (const json::exception& e) {
    // A number beyond double, e.g. "[json.exception.out_of_range.406] number overflow ...".
    const std::string what = e.what();
    const auto at = what.find("] ");
    throw ConfigError("",
                      "malformed JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
  }
}

json ReadJsonFile(const std::string& file) {
  std::error_code error;
  if (std::filesystem::is_directory(file, error))
    throw ConfigError::AboutFile("is a folder, not a JSON file");
  errno = 0;
  std::ifstream in(file);
  if (!in) {
    // The system's reason (no such file, permission denied), as the user can act on it.
    const int reason = errno;
    throw ConfigError::AboutFile(std::string("cannot open: ") +
                                 (reason != 0 ? std::strerror(reason) : "unreadable"));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return ParseJsonText(buffer.str());
}

std::string OverridePointer(const std::string& override_text) {
  const auto eq = override_text.find('=');
  if (eq == std::string::npos || eq == 0)
    return "";
  std::string path = override_text.substr(0, eq);
  if (path[0] != '/') {
    for (auto& c : path)
      c = (c == '.') ? '/' : c;
    path = "/" + path;
  }
  return path;
}

namespace {

// Whether JSON pointer `inner` is `outer` or lies inside it ("/wifi/width" in "/wifi").
bool AtOrInside(const std::string& inner, const std::string& outer) {
  return inner.compare(0, outer.size(), outer) == 0 &&
         (inner.size() == outer.size() || inner[outer.size()] == '/');
}

}  // namespace

ConfigError BlameOverride(const ConfigError& error, const std::vector<std::string>& overrides) {
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string pointer = OverridePointer(*it);
    if (!pointer.empty() && AtOrInside(error.path(), pointer))
      return ConfigError("--set " + *it, error.describe());
  }
  return error;
}

void ApplyOverrides(json& document, const std::vector<std::string>& overrides) {
  for (const auto& item : overrides) {
    const std::string path = OverridePointer(item);
    if (path.empty())
      throw ConfigError("--set " + item, "expected path=value");
    const std::string text = item.substr(item.find('=') + 1);
    json value;
    try {
      value = json::parse(text);
    } catch (const json::parse_error&) {
      value = text;  // a bare word such as adhoc
    } catch (const json::exception&) {
      throw ConfigError("--set " + item, "the value is not a number a double can hold");
    }
    try {
      const json::json_pointer pointer(path);
      // Creating objects on the way is fine: unknown keys are rejected by ParseScenario.
      if (!pointer.parent_pointer().empty() && !document.contains(pointer.parent_pointer())) {
        document[pointer.parent_pointer()] = json::object();
      }
      const json& parent = document[pointer.parent_pointer()];
      if (parent.is_array()) {
        const std::string last = pointer.back();
        if (last.find_first_not_of("0123456789") != std::string::npos ||
            std::stoul(last) >= parent.size()) {
          throw ConfigError(path, "array index out of range");
        }
      }
      document[pointer] = value;
    } catch (const json::exception& e) {
      throw ConfigError(path, std::string("cannot set: ") + e.what());
    }
  }
}

Scenario ParseScenario(const json& document) {
  ObjectReader r(document, "");
  Scenario s = ScenarioDefaults();
  ReadSettings(r, ScenarioSettings(), s);
  s.venue = ReadSection(r.Child("venue"), VenueSettings());
  s.wifi = ReadSection(r.Child("wifi"), WifiSettings());
  const PhyProfile phy{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns,
                       s.wifi.spatial_streams};
  if (const json* v = r.Child("buildings")) {
    if (!v->is_array())
      throw ConfigError("/buildings", "expected an array, got " + TypeName(*v));
    for (std::size_t i = 0; i < v->size(); ++i) {
      s.buildings.push_back(ReadBuilding((*v)[i], JoinPath("/buildings", i), i));
    }
  }
  const json* ues = r.Child("ues");
  if (!ues)
    throw ConfigError("/ues", "is required (at least one UE)");
  if (!ues->is_array() || ues->empty())
    throw ConfigError("/ues", "expected a non-empty array");
  for (std::size_t i = 0; i < ues->size(); ++i) {
    s.ues.push_back(ReadUe((*ues)[i], JoinPath("/ues", i), i, phy));
  }
  const json* uav = r.Child("uav");
  const json* uavs = r.Child("uavs");
  if (uav && uavs)
    throw ConfigError("/uavs", "give \"uav\" (one UAV) or \"uavs\", not both");
  s.uavs.clear();
  if (uavs) {
    if (!uavs->is_array() || uavs->empty()) {
      throw ConfigError("/uavs", "expected a non-empty array of UAVs");
    }
    if (uavs->size() > kMaxUavs) {
      throw ConfigError("/uavs", std::to_string(uavs->size()) + " UAVs; at most " +
                                     std::to_string(kMaxUavs) + " are supported");
    }
    s.uavs_listed = true;
    for (std::size_t i = 0; i < uavs->size(); ++i) {
      s.uavs.push_back(
          ReadUav((*uavs)[i], s.venue, JoinPath("/uavs", i), "uav" + std::to_string(i + 1)));
    }
  } else {
    s.uavs.push_back(ReadUav(uav ? *uav : json::object(), s.venue, "/uav", "uav"));
  }
  s.traffic = ReadSection(r.Child("traffic"), TrafficSettings());
  s.simulation = ReadSection(r.Child("simulation"), SimulationSettings());
  const json* env = r.Child("env");
  s.env = ReadEnv(env ? *env : json::object());
  // Without an "agent" section too: the defaults depend on the number of UAVs.
  const json* agent = r.Child("agent");
  s.agent = ReadAgent(agent ? *agent : json::object(), s.uavs.size());
  r.Finish();
  // SAC acts on displacements, DQN and PPO choose among the moves.
  const bool continuous_agent = s.agent.algorithm == "sac";
  if (continuous_agent != (s.env.action_space == "continuous")) {
    throw ConfigError("/agent/algorithm", s.agent.algorithm + " needs env.action_space \"" +
                                              (continuous_agent ? "continuous" : "discrete") +
                                              "\", not \"" + s.env.action_space + "\"");
  }
  CheckUeEncoder(s);
  CheckScenarioGeometry(s);
  return s;
}

namespace {

template <typename Spec>
json ListJson(const std::vector<Spec>& list, const SettingsTable<Spec>& table) {
  json out = json::array();
  for (const Spec& element : list)
    out.push_back(SettingsJson(element, table));
  return out;
}

json UavsJson(const Scenario& s) {
  json uavs = json::array();
  for (const auto& u : s.uavs) {
    json uav = SettingsJson(u, UavSettings());
    // A single UAV's document stays as it was before names and channels existed.
    if (!s.uavs_listed && u.name == "uav")
      uav.erase("name");
    uavs.push_back(uav);
  }
  return uavs;
}

}  // namespace

json ToJson(const Scenario& s) {
  json env = SettingsJson(s.env, EnvSettings());
  env["reward"] = SettingsJson(s.env.reward, RewardSettings());
  json document = {{"venue", SettingsJson(s.venue, VenueSettings())},
                   {"buildings", ListJson(s.buildings, BuildingSettings())},
                   {"ues", ListJson(s.ues, UeSettings())},
                   {"wifi", SettingsJson(s.wifi, WifiSettings())},
                   {"traffic", SettingsJson(s.traffic, TrafficSettings())},
                   {"simulation", SettingsJson(s.simulation, SimulationSettings())},
                   {"env", env},
                   {"agent", AgentJson(s.agent)}};
  WriteSettings(s, ScenarioSettings(), document);
  const json uavs = UavsJson(s);
  if (s.uavs_listed) {
    document["uavs"] = uavs;
  } else {
    document["uav"] = uavs[0];
  }
  return document;
}

const std::vector<std::string>& AllAlgorithms() {
  static const std::vector<std::string> all = NameList(kAlgorithms);
  return all;
}

std::vector<std::string> AlgorithmOverrides(const std::string& algorithm) {
  return AlgorithmDefaults(algorithm).overrides;
}

}  // namespace rlpos
