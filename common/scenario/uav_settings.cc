#include "common/scenario/uav_settings.h"

#include <tuple>

namespace rlpos {
namespace {

using nlohmann::json;

// uav.max_speed and uav.max_climb: above 0, at most kMaxUavSpeed.
NumberRange SpeedLimit() {
  return {0.0, kMaxUavSpeed, true};
}

void ReadPosition(UavSpec& uav, const json& v, const std::string& path) {
  uav.initial = ReadVec3(v, path);
}

json PositionJson(const UavSpec& uav) {
  return Vec3Json(uav.initial);
}

// {"x": [min, max], "y": ..., "z": ...}; an axis left out keeps the venue's.
void ReadZone(UavSpec& uav, const json& v, const std::string& path) {
  ObjectReader z(v, path);
  if (const json* x = z.Child("x"))
    std::tie(uav.zone.xmin, uav.zone.xmax) = ReadInterval(*x, z.PathOf("x"), true);
  if (const json* y = z.Child("y"))
    std::tie(uav.zone.ymin, uav.zone.ymax) = ReadInterval(*y, z.PathOf("y"), true);
  if (const json* h = z.Child("z"))
    std::tie(uav.zone.zmin, uav.zone.zmax) = ReadInterval(*h, z.PathOf("z"), true);
  z.Finish();
}

json ZoneJson(const UavSpec& uav) {
  const Box& z = uav.zone;
  return {{"x", {z.xmin, z.xmax}}, {"y", {z.ymin, z.ymax}}, {"z", {z.zmin, z.zmax}}};
}

}  // namespace

const SettingsTable<UavSpec>& UavSettings() {
  static const SettingsTable<UavSpec> table{
      "uav",
      "/uav",
      "A UAV: \"uav\" for one, or each of \"uavs\" (at most 8; docs/several-uavs.md). Its "
      "position is the baseline.",
      {{"name", &UavSpec::name, NoRange(),
        "its name (\"uav\"; in \"uavs\", \"uav<i>\" counting from 1); a UE's \"uav\" names it"},
       {"position", CustomValue<UavSpec>{ReadPosition, PositionJson, "[x, y, z]"}, NoRange(),
        "initial position, the baseline; default the venue's centre at 10 m", "m"},
       {"zone", CustomValue<UavSpec>{ReadZone, ZoneJson, "{\"x\", \"y\", \"z\"}: [min, max] each"},
        NoRange(), "where the UAV may go; default the venue, z in [1, venue.height]", "m"},
       {"channel",
        &UavSpec::channel,
        Integers(1, 233),
        "its Wi-Fi channel; unset (0): wifi.channel for the first UAV, then the next channels of "
        "wifi.width in ns-3's channel table. UAVs given the same channel share the air",
        "",
        {},
        nullptr,
        [](const UavSpec& u) { return u.channel > 0; }},
       {"max_speed",
        &UavSpec::max_speed,
        SpeedLimit(),
        "how fast it flies horizontally when a positioner re-decides during a run (rlpos-sim "
        "track)",
        "m/s",
        {},
        nullptr,
        [](const UavSpec& u) { return u.max_speed != UavSpec{}.max_speed; }},
       {"max_climb",
        &UavSpec::max_climb,
        SpeedLimit(),
        "likewise, vertically",
        "m/s",
        {},
        nullptr,
        [](const UavSpec& u) { return u.max_climb != UavSpec{}.max_climb; }}},
      [](const UavSpec& u, const ObjectReader& r) {
        if (u.name.empty())
          throw ConfigError(r.PathOf("name"), "must not be empty");
      }};
  return table;
}

}  // namespace rlpos
