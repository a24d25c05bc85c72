// Gym, ns3Sim.configSim and ns3Sim.defaultValues' radio and run settings.
#include <algorithm>
#include <climits>
#include <map>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"
#include "common/scenario/number_text.h"
#include "common/scenario_import/rlpos3_parts.h"

namespace rlpos {
namespace {

using nlohmann::json;

// One of `allowed` (source value -> ours), or a ConfigError listing the source values.
std::string Choose(Rlpos3Object& object, const std::string& key, const std::string& fallback,
                   const std::map<std::string, std::string>& allowed) {
  const std::string value = object.String(key, fallback);
  const auto it = allowed.find(value);
  if (it != allowed.end())
    return it->second;
  std::string names;
  for (const auto& [name, ours] : allowed)
    names += (names.empty() ? "\"" : ", \"") + name + "\"";
  throw ConfigError(object.PathOf(key), "unknown value \"" + value + "\" (expected " + names + ")");
}

double Bound(Rlpos3Object& venue_size, const std::string& key) {
  return venue_size.RequiredNumber(key);
}

void CheckAbove(Rlpos3Object& venue_size, const std::string& max_key, double max, double min) {
  if (max <= min) {
    throw ConfigError(venue_size.PathOf(max_key), "must be above its min (" + FormatNumber(min) +
                                                      "), got " + FormatNumber(max));
  }
}

// ConstantRateWifiManager at the source's fixedMCS, taken from the standard's mode list.
ObjectSpec FixedRateManager(Rlpos3Object& config_sim, const std::string& standard) {
  const std::map<std::string, std::string> lists = {
      {"802.11n", "htDataRates"}, {"802.11ac", "vhtDataRates"}, {"802.11ax", "heDataRates"}};
  const std::string list_key = lists.at(standard);
  const long long mcs = Rlpos3Integer(config_sim.Required("fixedMCS", "the MCS of \"fixed\""),
                                      config_sim.PathOf("fixedMCS"), 0, 11);
  const json& modes = config_sim.Required(list_key, "the " + standard + " modes of \"fixed\"");
  const std::string path = config_sim.PathOf(list_key);
  if (!modes.is_array() || static_cast<long long>(modes.size()) <= mcs) {
    throw ConfigError(path, "expected an array of ns-3 WifiModes with an entry for fixedMCS " +
                                std::to_string(mcs));
  }
  const json& mode = modes[static_cast<std::size_t>(mcs)];
  if (!mode.is_string())
    throw ConfigError(JoinPath(path, static_cast<std::size_t>(mcs)), "expected a WifiMode name");
  for (const auto& [other_standard, other_key] : lists) {
    if (other_key != list_key)
      config_sim.NotCarried(other_key, "RLpos-3 reads it only for " + other_standard);
  }
  return {"ns3::ConstantRateWifiManager",
          {{"DataMode", mode.get<std::string>()}, {"ControlMode", mode.get<std::string>()}}};
}

void ReadRateManager(Rlpos3Object& config_sim, Scenario& s) {
  const std::string kind = Choose(config_sim, "RemotStManager", "id",
                                  {{"id", "ideal"}, {"min", "minstrel"}, {"fixed", "fixed"}});
  if (kind == "fixed") {
    s.wifi.rate_manager = FixedRateManager(config_sim, s.wifi.standard);
    return;
  }
  s.wifi.rate_manager = {kind == "ideal" ? "ns3::IdealWifiManager" : "ns3::MinstrelHtWifiManager",
                         json::object()};
  for (const char* key : {"fixedMCS", "htDataRates", "vhtDataRates", "heDataRates"})
    config_sim.NotCarried(key, "RLpos-3 reads it only when RemotStManager is \"fixed\"");
}

// RLpos-3's moves: left/right along y, back/front along x, down/up along z, same = stay.
void ReadDirections(Rlpos3Object& config_sim, Scenario& s) {
  const json* v = config_sim.Optional("UAV_directions");
  if (!v)
    return;
  const std::string path = config_sim.PathOf("UAV_directions");
  if (!v->is_array() || v->empty())
    throw ConfigError(path, "expected a non-empty array of moves");
  const std::map<std::string, std::string> moves = {
      {"left", "backward"}, {"right", "forward"}, {"back", "left"}, {"front", "right"},
      {"down", "down"},     {"up", "up"},         {"same", "stay"}};
  s.env.actions.clear();
  for (std::size_t i = 0; i < v->size(); ++i) {
    const json& move = (*v)[i];
    const auto it = move.is_string() ? moves.find(move.get<std::string>()) : moves.end();
    if (it == moves.end()) {
      throw ConfigError(JoinPath(path, i), "unknown move " + move.dump() +
                                               " (expected left, right, back, front, down, up "
                                               "or same)");
    }
    s.env.actions.push_back(it->second);
  }
}

}  // namespace

Rlpos3Frame ReadGym(Rlpos3Object& gym, Scenario& s) {
  Rlpos3Object venue_size = gym.Object("venueSize", "Xmin, Xmax, Ymin, Ymax, Zmin, Zmax");
  Rlpos3Frame f;
  f.xmin = Bound(venue_size, "Xmin");
  f.xmax = Bound(venue_size, "Xmax");
  f.ymin = Bound(venue_size, "Ymin");
  f.ymax = Bound(venue_size, "Ymax");
  f.zmin = Bound(venue_size, "Zmin");
  f.zmax = Bound(venue_size, "Zmax");
  CheckAbove(venue_size, "Xmax", f.xmax, f.xmin);
  CheckAbove(venue_size, "Ymax", f.ymax, f.ymin);
  CheckAbove(venue_size, "Zmax", f.zmax, std::max(f.zmin, 0.0));
  if (f.zmin < 0) {
    venue_size.Warn(
        "Zmin", FormatNumber(f.zmin) + " is below the ground: the UAV's zone starts at z = 0 here");
  }
  s.venue = {f.xmax - f.xmin, f.ymax - f.ymin, f.zmax};
  s.env.step = venue_size.Number("gridResolution", s.env.step);
  venue_size.Finish();
  s.env.decision_interval = gym.Number("decisionInterval", s.env.decision_interval);
  gym.NotCarried("logLevels", "RLpos-3's log switches; here log_level (stays \"warning\")");
  gym.NotCarried("bypass", "no equivalent in rlpos-sim's env");
  gym.Finish();
  return f;
}

void ReadConfigSim(Rlpos3Object& config_sim, Scenario& s) {
  s.wifi.standard = Choose(config_sim, "wifiStandard", "WIFI_STANDARD_80211ac",
                           {{"WIFI_STANDARD_80211n", "802.11n"},
                            {"WIFI_STANDARD_80211ac", "802.11ac"},
                            {"WIFI_STANDARD_80211ax", "802.11ax"}});
  s.traffic.protocol =
      Choose(config_sim, "trafficProtocol", "udp", {{"udp", "udp_cbr"}, {"tcp", "tcp_bulk"}});
  ReadRateManager(config_sim, s);
  ReadDirections(config_sim, s);
  if (config_sim.String("mobilityModel", "const") != "const") {
    config_sim.Warn("mobilityModel",
                    "RLpos-3 keeps every UE at a constant position whatever this says: static");
  }
  config_sim.NotCarried("enableGym", "rlpos-sim train runs its env in-process");
  config_sim.NotCarried("path", "RLpos-3's log folder; rlpos-sim train --out names the folder");
  config_sim.Finish();
}

void ReadRadio(Rlpos3Object& defaults, Scenario& s) {
  s.wifi.width_mhz = static_cast<int>(defaults.Integer("channelBW", s.wifi.width_mhz, 1, 100000));
  const int w = s.wifi.width_mhz;
  if ((w != 20 && w != 40 && w != 80 && w != 160) || (s.wifi.standard == "802.11n" && w > 40)) {
    throw ConfigError(defaults.PathOf("channelBW"),
                      std::to_string(w) + " MHz is not a channel width of " + s.wifi.standard);
  }
  s.wifi.guard_interval_ns =
      static_cast<int>(defaults.Integer("GuardInterval", s.wifi.guard_interval_ns, 1, 100000));
  s.wifi.channel = static_cast<int>(defaults.Integer("wifiChannelNumber", s.wifi.channel, 1, 233));
  s.wifi.noise_floor_dbm = defaults.Number("PN", s.wifi.noise_floor_dbm);
  s.wifi.antenna_gain_dbi = defaults.Number("antennaGain", s.wifi.antenna_gain_dbi);
  s.wifi.tx_power_dbm = defaults.Number("txpower", s.wifi.tx_power_dbm);
  s.simulation.seed =
      static_cast<std::uint32_t>(defaults.Integer("simSeed", s.simulation.seed, 0, UINT32_MAX));
  s.simulation.run = static_cast<std::uint64_t>(
      defaults.Integer("simRun", static_cast<long long>(s.simulation.run), 0, 9007199254740991LL));
  s.env.episode_duration = defaults.Number("simDuration", s.env.episode_duration);
  defaults.NotCarried("openGymPort", "rlpos-sim's env runs in-process, with no ns3-gym socket");
}

}  // namespace rlpos
