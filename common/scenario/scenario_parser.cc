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
#include "common/scenario/names.h"
#include "common/scenario/scenario_checks.h"

namespace rlpos {
namespace {

using nlohmann::json;

Vec3 ReadVec3(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) {
    throw ConfigError(path,
                      "expected [x, y, z], got " +
                          (v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v)));
  }
  return {CheckedNumber(v[0], JoinPath(path, 0), {}), CheckedNumber(v[1], JoinPath(path, 1), {}),
          CheckedNumber(v[2], JoinPath(path, 2), {})};
}

// [lo, hi] with lo < hi (or lo <= hi when `allow_point`).
std::pair<double, double> ReadInterval(const json& v, const std::string& path, bool allow_point) {
  if (!v.is_array() || v.size() != 2) {
    throw ConfigError(path, "expected [min, max], got " + TypeName(v));
  }
  const double lo = CheckedNumber(v[0], JoinPath(path, 0), {});
  const double hi = CheckedNumber(v[1], JoinPath(path, 1), {});
  if (hi < lo || (!allow_point && hi == lo)) {
    throw ConfigError(path, "min must be below max");
  }
  return {lo, hi};
}

ObjectSpec ReadObjectSpec(const json& v, const std::string& path) {
  ObjectReader r(v, path);
  ObjectSpec spec;
  spec.type = r.String("type", "");
  if (spec.type.empty())
    throw ConfigError(r.PathOf("type"), "is required (an ns-3 TypeId name)");
  if (const json* attributes = r.Child("attributes")) {
    if (!attributes->is_object()) {
      throw ConfigError(r.PathOf("attributes"), "expected an object, got " + TypeName(*attributes));
    }
    for (auto it = attributes->begin(); it != attributes->end(); ++it) {
      const std::string attribute_path = JoinPath(r.PathOf("attributes"), it.key());
      if (it->is_object()) {
        ReadObjectSpec(*it, attribute_path);  // nested spec: validate its shape now
      } else if (it->is_number()) {
        CheckedNumber(*it, attribute_path, {});
      } else if (!it->is_string() && !it->is_boolean()) {
        throw ConfigError(attribute_path, "expected a number, string, boolean or {\"type\": ...}");
      }
    }
    spec.attributes = *attributes;
  }
  r.Finish();
  return spec;
}

Venue ReadVenue(const json& v) {
  ObjectReader r(v, "/venue");
  Venue venue;
  venue.width = r.Number("width", venue.width, Positive());
  venue.depth = r.Number("depth", venue.depth, Positive());
  venue.height = r.Number("height", venue.height, Positive());
  r.Finish();
  return venue;
}

BuildingSpec ReadBuilding(const json& v, const std::string& path, std::size_t index) {
  ObjectReader r(v, path);
  BuildingSpec b;
  b.name = r.String("name", "building" + std::to_string(index));
  const json* x = r.Child("x");
  const json* y = r.Child("y");
  if (!x)
    throw ConfigError(r.PathOf("x"), "is required ([xmin, xmax])");
  if (!y)
    throw ConfigError(r.PathOf("y"), "is required ([ymin, ymax])");
  std::tie(b.xmin, b.xmax) = ReadInterval(*x, r.PathOf("x"), false);
  std::tie(b.ymin, b.ymax) = ReadInterval(*y, r.PathOf("y"), false);
  b.height = r.RequiredNumber("height", Positive());
  b.floors = static_cast<int>(r.Integer("floors", 1, 1, 200));
  if (const json* rooms = r.Child("rooms")) {
    if (!rooms->is_array() || rooms->size() != 2 || !(*rooms)[0].is_number_integer() ||
        !(*rooms)[1].is_number_integer() || (*rooms)[0].get<long long>() < 1 ||
        (*rooms)[1].get<long long>() < 1) {
      throw ConfigError(r.PathOf("rooms"), "expected [rooms_x, rooms_y], integers >= 1");
    }
    b.rooms_x = (*rooms)[0].get<int>();
    b.rooms_y = (*rooms)[1].get<int>();
  }
  b.type = r.String("type", b.type, {"residential", "office", "commercial"});
  b.walls = r.String("walls", b.walls,
                     {"wood", "concrete_with_windows", "concrete_without_windows", "stone_blocks"});
  r.Finish();
  return b;
}

// [x, y]: a point on the ground.
Vec3 ReadGroundPoint(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) {
    throw ConfigError(path,
                      "expected [x, y], got " +
                          (v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v)));
  }
  return {CheckedNumber(v[0], JoinPath(path, 0), {}), CheckedNumber(v[1], JoinPath(path, 1), {}),
          0.0};
}

MobilitySpec ReadMobility(const json& v, const std::string& path) {
  ObjectReader r(v, path);
  MobilitySpec m;
  m.model = *ParseMobilityModel(r.String("model", "static", MobilityModelNames()));
  switch (m.model) {
    case MobilityModel::kStatic:
      // Documents written before the other models carry random_walk's keys: read, unused.
      r.Number("speed", 1.0, Positive());
      r.Number("change_interval", 2.0, Positive());
      break;
    case MobilityModel::kRandomWalk: {
      auto& w = m.random_walk;
      w.speed = r.Number("speed", w.speed, Positive());
      w.change_interval = r.Number("change_interval", w.change_interval, Positive());
      break;
    }
    case MobilityModel::kRandomWaypoint: {
      auto& w = m.random_waypoint;
      if (const json* speed = r.Child("speed")) {
        std::tie(w.speed_min, w.speed_max) = ReadInterval(*speed, r.PathOf("speed"), true);
        CheckedNumber((*speed)[0], JoinPath(r.PathOf("speed"), 0), Positive());
      }
      w.pause = r.Number("pause", w.pause, NonNegative());
      break;
    }
    case MobilityModel::kGaussMarkov: {
      auto& g = m.gauss_markov;
      g.speed = r.Number("speed", g.speed, Positive());
      g.alpha = r.Number("alpha", g.alpha, Between(0.0, 1.0));
      g.step = r.Number("step", g.step, Positive());
      break;
    }
    case MobilityModel::kCrowd: {
      auto& c = m.crowd;
      const json* target = r.Child("target");
      if (!target)
        throw ConfigError(r.PathOf("target"), "is required ([x, y]: where the crowd gathers)");
      c.target = ReadGroundPoint(*target, r.PathOf("target"));
      c.radius = r.Number("radius", c.radius, NonNegative());
      c.speed = r.Number("speed", c.speed, Positive());
      c.start = r.Number("start", c.start, NonNegative());
      c.dwell = r.Number("dwell", c.dwell, NonNegative());
      break;
    }
  }
  r.Finish();
  return m;
}

UeSpec ReadUe(const json& v, const std::string& path, std::size_t index, const PhyProfile& phy) {
  ObjectReader r(v, path);
  UeSpec ue;
  ue.name = r.String("name", "ue" + std::to_string(index));
  ue.uav = r.String("uav", "");
  const json* position = r.Child("position");
  if (!position)
    throw ConfigError(r.PathOf("position"), "is required ([x, y, z])");
  ue.position = ReadVec3(*position, r.PathOf("position"));
  const json* demand = r.Child("demand");
  if (!demand)
    throw ConfigError(r.PathOf("demand"), "is required ({\"mbps\": R} or {\"mcs\": I})");
  ObjectReader d(*demand, r.PathOf("demand"));
  if (d.Has("mbps") == d.Has("mcs")) {
    throw ConfigError(d.path(), "give exactly one of \"mbps\" or \"mcs\"");
  }
  if (d.Has("mbps")) {
    ue.demand_mbps = d.RequiredNumber("mbps", Positive());
  } else {
    ue.demand_mcs = static_cast<int>(d.Integer("mcs", 0, 0, MaxMcs(phy.standard)));
    ue.demand_mbps = McsDataRateMbps(phy, ue.demand_mcs);
  }
  d.Finish();
  if (const json* mobility = r.Child("mobility")) {
    ue.mobility = ReadMobility(*mobility, r.PathOf("mobility"));
  }
  r.Finish();
  return ue;
}

// uav.max_speed and uav.max_climb: above 0, at most kMaxUavSpeed.
NumberRange SpeedLimit() {
  return {0.0, kMaxUavSpeed, true};
}

UavSpec ReadUav(const json& v, const Venue& venue, const std::string& path,
                const std::string& default_name) {
  ObjectReader r(v, path);
  UavSpec uav;
  uav.name = r.String("name", default_name);
  if (uav.name.empty())
    throw ConfigError(r.PathOf("name"), "must not be empty");
  uav.channel = static_cast<int>(r.Integer("channel", 0, 1, 233));
  uav.max_speed = r.Number("max_speed", uav.max_speed, SpeedLimit());
  uav.max_climb = r.Number("max_climb", uav.max_climb, SpeedLimit());
  uav.zone = {0, venue.width, 0, venue.depth, 1.0, venue.height};
  uav.initial = {venue.width / 2, venue.depth / 2, 10.0};
  if (const json* p = r.Child("position"))
    uav.initial = ReadVec3(*p, r.PathOf("position"));
  if (const json* zone = r.Child("zone")) {
    ObjectReader z(*zone, r.PathOf("zone"));
    if (const json* x = z.Child("x"))
      std::tie(uav.zone.xmin, uav.zone.xmax) = ReadInterval(*x, z.PathOf("x"), true);
    if (const json* y = z.Child("y"))
      std::tie(uav.zone.ymin, uav.zone.ymax) = ReadInterval(*y, z.PathOf("y"), true);
    if (const json* h = z.Child("z"))
      std::tie(uav.zone.zmin, uav.zone.zmax) = ReadInterval(*h, z.PathOf("z"), true);
    z.Finish();
  }
  r.Finish();
  return uav;
}

WifiSpec ReadWifi(const json& v) {
  ObjectReader r(v, "/wifi");
  WifiSpec w;
  w.standard = r.String("standard", w.standard, {"802.11n", "802.11ac", "802.11ax"});
  w.channel = static_cast<int>(r.Integer("channel", w.channel, 1, 233));
  w.width_mhz = static_cast<int>(r.Integer("width", w.width_mhz, 20, 160));
  if (w.width_mhz != 20 && w.width_mhz != 40 && w.width_mhz != 80 && w.width_mhz != 160) {
    throw ConfigError(r.PathOf("width"), "must be 20, 40, 80 or 160 MHz");
  }
  if (w.standard == "802.11n" && w.width_mhz > 40) {
    throw ConfigError(r.PathOf("width"), "802.11n supports 20 or 40 MHz");
  }
  w.guard_interval_ns =
      static_cast<int>(r.Integer("guard_interval", w.guard_interval_ns, 400, 3200));
  const bool he = w.standard == "802.11ax";
  const int gi = w.guard_interval_ns;
  if (he ? (gi != 800 && gi != 1600 && gi != 3200) : (gi != 400 && gi != 800)) {
    throw ConfigError(r.PathOf("guard_interval"),
                      he ? "802.11ax guard interval must be 800, 1600 or 3200 ns"
                         : w.standard + " guard interval must be 400 or 800 ns");
  }
  w.spatial_streams = static_cast<int>(r.Integer("spatial_streams", w.spatial_streams, 1, 4));
  w.tx_power_dbm = r.Number("tx_power", w.tx_power_dbm, Between(-30, 40));
  w.antenna_gain_dbi = r.Number("antenna_gain", w.antenna_gain_dbi, Between(-30, 30));
  w.noise_floor_dbm = r.Number("noise_floor", w.noise_floor_dbm, Between(-140, 0));
  const double thermal = ThermalNoiseDbm(w.width_mhz);
  if (w.noise_floor_dbm < thermal) {
    throw ConfigError(r.PathOf("noise_floor"), "is below the thermal noise of a " +
                                                   std::to_string(w.width_mhz) + " MHz channel (" +
                                                   std::to_string(thermal).substr(0, 6) + " dBm)");
  }
  if (const json* rm = r.Child("rate_manager"))
    w.rate_manager = ReadObjectSpec(*rm, r.PathOf("rate_manager"));
  w.mode = r.String("mode", w.mode, {"adhoc", "ap_sta"});
  w.rts_cts = r.Bool("rts_cts", w.rts_cts);
  r.Finish();
  return w;
}

TrafficSpec ReadTraffic(const json& v) {
  ObjectReader r(v, "/traffic");
  TrafficSpec t;
  t.protocol = r.String("protocol", t.protocol, {"udp_cbr", "tcp_bulk"});
  t.packet_size = static_cast<int>(r.Integer("packet_size", t.packet_size, 64, 65000));
  r.Finish();
  return t;
}

SimulationSpec ReadSimulation(const json& v) {
  ObjectReader r(v, "/simulation");
  SimulationSpec s;
  s.duration = r.Number("duration", s.duration, Positive());
  s.warmup = r.Number("warmup", s.warmup, NonNegative());
  if (s.warmup >= s.duration) {
    throw ConfigError(r.PathOf("warmup"), "must be shorter than the duration");
  }
  s.seed = static_cast<std::uint32_t>(r.Integer("seed", s.seed, 1, 4294967295LL));
  s.run = static_cast<std::uint64_t>(
      r.Integer("run", static_cast<long long>(s.run), 0, 9007199254740991LL));
  r.Finish();
  return s;
}

std::vector<std::string> ReadStringList(const json& v, const std::string& path,
                                        const std::vector<std::string>& allowed) {
  if (!v.is_array() || v.empty())
    throw ConfigError(path, "expected a non-empty array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    // Reuse the enum check of ObjectReader through a one-key object.
    const json wrapper = {{"value", v[i]}};  // outlives the reader, which keeps a reference
    ObjectReader item(wrapper, path);
    try {
      out.push_back(item.String("value", "", allowed));
    } catch (const ConfigError& e) {
      throw ConfigError(JoinPath(path, i), e.problem());
    }
  }
  return out;
}

EnvSpec ReadEnv(const json& v) {
  ObjectReader r(v, "/env");
  EnvSpec e;
  e.fidelity = r.String("fidelity", e.fidelity, NameList(kFidelities));
  e.step = r.Number("step", e.step, Positive());
  if (const json* a = r.Child("actions")) {
    e.actions =
        ReadStringList(*a, r.PathOf("actions"),
                       {"up", "down", "forward", "backward", "left", "right", "stay", "to_best"});
  }
  if (const json* o = r.Child("observations")) {
    e.observations = ReadStringList(*o, r.PathOf("observations"), NameList(kObservations));
  }
  e.observed_ues = static_cast<int>(r.Integer("observed_ues", e.observed_ues, 1, 64));
  e.height_map = static_cast<int>(r.Integer("height_map", e.height_map, 1, 33));
  if (e.height_map % 2 == 0)
    throw ConfigError(r.PathOf("height_map"), "must be odd (the UAV is over the middle cell)");
  e.coverage_map = static_cast<int>(r.Integer("coverage_map", e.coverage_map, 1, 16));
  e.coverage_refine = static_cast<int>(r.Integer("coverage_refine", e.coverage_refine, 0, 8));
  e.decision_interval = r.Number("decision_interval", e.decision_interval, Positive());
  e.episode_duration = r.Number("episode_duration", e.episode_duration, Positive());
  e.action_mask = r.Bool("action_mask", e.action_mask);
  e.action_space = r.String("action_space", e.action_space, {"discrete", "continuous"});
  e.turn_steps = static_cast<int>(r.Integer("turn_steps", e.turn_steps, 1, 1000000));
  if (e.decision_interval > e.episode_duration) {
    throw ConfigError(r.PathOf("decision_interval"), "must not exceed the episode duration");
  }
  if (std::find(e.actions.begin(), e.actions.end(), "to_best") != e.actions.end() &&
      std::find(e.observations.begin(), e.observations.end(), "coverage") == e.observations.end()) {
    throw ConfigError(r.PathOf("actions"),
                      "\"to_best\" moves towards the coverage map's best: add \"coverage\" to "
                      "env.observations");
  }
  if (const json* rw = r.Child("reward")) {
    ObjectReader w(*rw, r.PathOf("reward"));
    e.reward.name = w.String("name", e.reward.name, {"paper", "demand_aware"});
    e.reward.w1 = w.Number("w1", e.reward.w1, NonNegative());
    e.reward.w2 = w.Number("w2", e.reward.w2, NonNegative());
    e.reward.w3 = w.Number("w3", e.reward.name == "demand_aware" ? 0.2 : 0.0, NonNegative());
    w.Finish();
  } else if (e.reward.name == "demand_aware") {
    e.reward.w3 = 0.2;
  }
  r.Finish();
  return e;
}

// An algorithm's own object ("agent.ppo", "agent.sac"): its declared hyperparameters only.
template <typename Spec>
Spec ReadAlgorithm(const json& v, const HyperparameterTable<Spec>& table) {
  ObjectReader r(v, table.path);
  Spec spec;
  ReadHyperparameters(r, table, spec);
  r.Finish();
  return spec;
}

std::vector<int> ReadHidden(const json& h, const std::string& path) {
  if (!h.is_array() || h.empty())
    throw ConfigError(path, "expected [units, ...]");
  std::vector<int> hidden;
  for (std::size_t i = 0; i < h.size(); ++i) {
    hidden.push_back(static_cast<int>(CheckedNumber(h[i], JoinPath(path, i), Between(1, 4096))));
  }
  return hidden;
}

std::vector<int> ReadUeEncoder(const json& e, const std::string& path) {
  if (!e.is_array())
    throw ConfigError(path, "expected [units, ...] (or [] for none)");
  if (e.size() > static_cast<std::size_t>(kMaxUeEncoderLayers)) {
    throw ConfigError(
        path, std::to_string(e.size()) + " layers; at most " + std::to_string(kMaxUeEncoderLayers));
  }
  std::vector<int> widths;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::string at = JoinPath(path, i);
    const double units = CheckedNumber(e[i], at, Between(1, kMaxUeEncoderWidth));
    if (units != std::floor(units))
      throw ConfigError(at, "expected an integer");
    widths.push_back(static_cast<int>(units));
  }
  return widths;
}

AgentSpec ReadAgent(const json& v, std::size_t uavs) {
  ObjectReader r(v, "/agent");
  AgentSpec a;
  a.algorithm = r.String("algorithm", a.algorithm, AllAlgorithms());
  static_cast<AgentCommonSpec&>(a) = AgentCommonDefaults(a.algorithm, uavs);
  if (const json* h = r.Child("hidden"))
    a.hidden = ReadHidden(*h, r.PathOf("hidden"));
  if (const json* e = r.Child("ue_encoder"))
    a.ue_encoder = ReadUeEncoder(*e, r.PathOf("ue_encoder"));
  ReadHyperparameters(r, DqnHyperparameters(), a.dqn);
  ReadHyperparameters(r, AgentCommonHyperparameters(), static_cast<AgentCommonSpec&>(a));
  if (const json* p = r.Child("ppo"))
    a.ppo = ReadAlgorithm(*p, PpoHyperparameters());
  const json* sac = r.Child("sac");
  if (sac)
    a.sac = ReadAlgorithm(*sac, SacHyperparameters());
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
  json agent = {{"algorithm", a.algorithm}, {"hidden", a.hidden}};
  WriteHyperparameters(a.dqn, DqnHyperparameters(), agent);
  WriteHyperparameters<AgentCommonSpec>(a, AgentCommonHyperparameters(), agent);
  WriteHyperparameters(a.ppo, PpoHyperparameters(), agent["ppo"]);
  WriteHyperparameters(a.sac, SacHyperparameters(), agent["sac"]);
  if (!a.ue_encoder.empty())  // absent when off: documents stay as they were before it
    agent["ue_encoder"] = a.ue_encoder;
  return agent;
}

json Vec3Json(const Vec3& v) {
  return json::array({v.x, v.y, v.z});
}
json SpecJson(const ObjectSpec& s) {
  return {{"type", s.type}, {"attributes", s.attributes}};
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
  Scenario s;
  s.name = r.String("name", "scenario");
  s.description = r.String("description", "");
  if (const json* v = r.Child("venue"))
    s.venue = ReadVenue(*v);
  if (const json* v = r.Child("wifi"))
    s.wifi = ReadWifi(*v);
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
  if (const json* v = r.Child("traffic"))
    s.traffic = ReadTraffic(*v);
  s.propagation = DefaultPropagation();
  if (const json* v = r.Child("propagation"))
    s.propagation = ReadObjectSpec(*v, "/propagation");
  if (const json* v = r.Child("simulation"))
    s.simulation = ReadSimulation(*v);
  s.log_level = r.String("log_level", s.log_level, {"error", "warning", "info", "debug"});
  if (const json* v = r.Child("env"))
    s.env = ReadEnv(*v);
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

json BuildingsJson(const Scenario& s) {
  json buildings = json::array();
  for (const auto& b : s.buildings) {
    buildings.push_back({{"name", b.name},
                         {"x", {b.xmin, b.xmax}},
                         {"y", {b.ymin, b.ymax}},
                         {"height", b.height},
                         {"floors", b.floors},
                         {"rooms", {b.rooms_x, b.rooms_y}},
                         {"type", b.type},
                         {"walls", b.walls}});
  }
  return buildings;
}

// The model and its own parameters only.
json MobilityJson(const MobilitySpec& m) {
  json out = {{"model", MobilityModelName(m.model)}};
  switch (m.model) {
    case MobilityModel::kStatic:
      break;
    case MobilityModel::kRandomWalk:
      out["speed"] = m.random_walk.speed;
      out["change_interval"] = m.random_walk.change_interval;
      break;
    case MobilityModel::kRandomWaypoint:
      out["speed"] = {m.random_waypoint.speed_min, m.random_waypoint.speed_max};
      out["pause"] = m.random_waypoint.pause;
      break;
    case MobilityModel::kGaussMarkov:
      out["speed"] = m.gauss_markov.speed;
      out["alpha"] = m.gauss_markov.alpha;
      out["step"] = m.gauss_markov.step;
      break;
    case MobilityModel::kCrowd:
      out["target"] = {m.crowd.target.x, m.crowd.target.y};
      out["radius"] = m.crowd.radius;
      out["speed"] = m.crowd.speed;
      out["start"] = m.crowd.start;
      out["dwell"] = m.crowd.dwell;
      break;
  }
  return out;
}

json UesJson(const Scenario& s) {
  json ues = json::array();
  for (const auto& u : s.ues) {
    json demand = u.demand_mcs >= 0 ? json{{"mcs", u.demand_mcs}} : json{{"mbps", u.demand_mbps}};
    json ue = {{"name", u.name},
               {"position", Vec3Json(u.position)},
               {"demand", demand},
               {"mobility", MobilityJson(u.mobility)}};
    if (!u.uav.empty())
      ue["uav"] = u.uav;
    ues.push_back(ue);
  }
  return ues;
}

json UavsJson(const Scenario& s) {
  json uavs = json::array();
  for (const auto& u : s.uavs) {
    const Box& z = u.zone;
    json uav = {
        {"position", Vec3Json(u.initial)},
        {"zone", {{"x", {z.xmin, z.xmax}}, {"y", {z.ymin, z.ymax}}, {"z", {z.zmin, z.zmax}}}}};
    // A single UAV's document stays as it was before names and channels existed.
    if (s.uavs_listed || u.name != "uav")
      uav["name"] = u.name;
    if (u.channel > 0)
      uav["channel"] = u.channel;
    // Absent when default: documents written before motion limits existed stay as they were.
    if (u.max_speed != UavSpec{}.max_speed)
      uav["max_speed"] = u.max_speed;
    if (u.max_climb != UavSpec{}.max_climb)
      uav["max_climb"] = u.max_climb;
    uavs.push_back(uav);
  }
  return uavs;
}

}  // namespace

json ToJson(const Scenario& s) {
  const json uavs = UavsJson(s);
  json document = {
      {"name", s.name},
      {"description", s.description},
      {"venue", {{"width", s.venue.width}, {"depth", s.venue.depth}, {"height", s.venue.height}}},
      {"buildings", BuildingsJson(s)},
      {"ues", UesJson(s)},
      {"wifi",
       {{"standard", s.wifi.standard},
        {"channel", s.wifi.channel},
        {"width", s.wifi.width_mhz},
        {"guard_interval", s.wifi.guard_interval_ns},
        {"spatial_streams", s.wifi.spatial_streams},
        {"tx_power", s.wifi.tx_power_dbm},
        {"antenna_gain", s.wifi.antenna_gain_dbi},
        {"noise_floor", s.wifi.noise_floor_dbm},
        {"rate_manager", SpecJson(s.wifi.rate_manager)},
        {"mode", s.wifi.mode},
        {"rts_cts", s.wifi.rts_cts}}},
      {"traffic", {{"protocol", s.traffic.protocol}, {"packet_size", s.traffic.packet_size}}},
      {"propagation", SpecJson(s.propagation)},
      {"simulation",
       {{"duration", s.simulation.duration},
        {"warmup", s.simulation.warmup},
        {"seed", s.simulation.seed},
        {"run", s.simulation.run}}},
      {"log_level", s.log_level},
      {"env",
       {{"fidelity", s.env.fidelity},
        {"step", s.env.step},
        {"actions", s.env.actions},
        {"observations", s.env.observations},
        {"decision_interval", s.env.decision_interval},
        {"episode_duration", s.env.episode_duration},
        {"action_mask", s.env.action_mask},
        {"action_space", s.env.action_space},
        {"reward",
         {{"name", s.env.reward.name},
          {"w1", s.env.reward.w1},
          {"w2", s.env.reward.w2},
          {"w3", s.env.reward.w3}}}}},
      {"agent", AgentJson(s.agent)}};
  if (s.env.turn_steps != 1)  // absent before several UAVs existed: documents stay as they were
    document["env"]["turn_steps"] = s.env.turn_steps;
  // Likewise absent before the general observations, unless they are used or set.
  const EnvSpec defaults;
  const bool general =
      std::any_of(s.env.observations.begin(), s.env.observations.end(),
                  [](const std::string& f) { return IsOneOf(f, kGeneralObservations); });
  if (general || s.env.observed_ues != defaults.observed_ues)
    document["env"]["observed_ues"] = s.env.observed_ues;
  if (general || s.env.height_map != defaults.height_map)
    document["env"]["height_map"] = s.env.height_map;
  if (general || s.env.coverage_map != defaults.coverage_map)
    document["env"]["coverage_map"] = s.env.coverage_map;
  if (s.env.coverage_refine != defaults.coverage_refine)  // absent before it existed
    document["env"]["coverage_refine"] = s.env.coverage_refine;
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
  return {"agent.algorithm=" + algorithm,
          std::string("env.action_space=") + (algorithm == "sac" ? "continuous" : "discrete")};
}

}  // namespace rlpos
