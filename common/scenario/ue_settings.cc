#include "common/scenario/ue_settings.h"

#include <limits>

namespace rlpos {
namespace {

using nlohmann::json;

void ReadPosition(UeSpec& ue, const json& v, const std::string& path) {
  ue.position = ReadVec3(v, path);
}
json PositionJson(const UeSpec& ue) {
  return Vec3Json(ue.position);
}

// {"mbps": R} or {"mcs": I}. An MCS's rate, and the highest MCS, follow the scenario's PHY: the
// parser resolves them once "wifi" is read.
void ReadDemand(UeSpec& ue, const json& v, const std::string& path) {
  ObjectReader d(v, path);
  if (d.Has("mbps") == d.Has("mcs"))
    throw ConfigError(d.path(), "give exactly one of \"mbps\" or \"mcs\"");
  if (d.Has("mbps")) {
    ue.demand_mbps = d.RequiredNumber("mbps", Positive());
    ue.demand_mcs = -1;
  } else {
    ue.demand_mcs = static_cast<int>(d.Integer("mcs", 0, 0, std::numeric_limits<int>::max()));
  }
  d.Finish();
}
json DemandJson(const UeSpec& ue) {
  return ue.demand_mcs >= 0 ? json{{"mcs", ue.demand_mcs}} : json{{"mbps", ue.demand_mbps}};
}

void ReadUeMobility(UeSpec& ue, const json& v, const std::string& path) {
  ue.mobility = ReadMobility(v, path);
}
json UeMobilityJson(const UeSpec& ue) {
  return MobilityJson(ue.mobility);
}

}  // namespace

const SettingsTable<UeSpec>& UeSettings() {
  static const SettingsTable<UeSpec> table{
      "ue",
      "/ues/<i>",
      "A UE: a station on the ground with an uplink demand (at least one).",
      {{"name", &UeSpec::name, NoRange(), "its name (\"ue<i>\", counting from 0)"},
       {"uav",
        &UeSpec::uav,
        NoRange(),
        "a UAV's name: the UE is always served by it; unset: by the UAV of best SNR",
        "",
        {},
        nullptr,
        [](const UeSpec& ue) { return !ue.uav.empty(); }},
       {"position",
        CustomValue<UeSpec>{ReadPosition, PositionJson, "[x, y, z]"},
        NoRange(),
        "its position (z: the antenna's height); where a moving UE starts",
        "m",
        {},
        "[x, y, z]"},
       {"demand",
        CustomValue<UeSpec>{ReadDemand, DemandJson, "{\"mbps\": R} or {\"mcs\": I}"},
        NoRange(),
        "its uplink demand: a rate in Mbit/s, or an MCS, whose rate with the scenario's PHY it "
        "then is (at most the standard's highest MCS)",
        "",
        {},
        "{\"mbps\": R} or {\"mcs\": I}"},
       {"mobility", CustomValue<UeSpec>{ReadUeMobility, UeMobilityJson, "{\"model\", ...}"},
        NoRange(),
        "how it moves: \"model\" (static, random_walk, random_waypoint, gauss_markov, crowd) and "
        "that model's settings (the mobility.* tables); default {\"model\": \"static\"}"}}};
  return table;
}

}  // namespace rlpos
