#include "common/scenario/building_settings.h"

#include <tuple>

namespace rlpos {
namespace {

using nlohmann::json;

void ReadX(BuildingSpec& b, const json& v, const std::string& path) {
  std::tie(b.xmin, b.xmax) = ReadInterval(v, path, false);
}
json XJson(const BuildingSpec& b) {
  return {b.xmin, b.xmax};
}
void ReadY(BuildingSpec& b, const json& v, const std::string& path) {
  std::tie(b.ymin, b.ymax) = ReadInterval(v, path, false);
}
json YJson(const BuildingSpec& b) {
  return {b.ymin, b.ymax};
}

void ReadRooms(BuildingSpec& b, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer() ||
      v[0].get<long long>() < 1 || v[1].get<long long>() < 1) {
    throw ConfigError(path, "expected [rooms_x, rooms_y], integers >= 1");
  }
  b.rooms_x = v[0].get<int>();
  b.rooms_y = v[1].get<int>();
}
json RoomsJson(const BuildingSpec& b) {
  return {b.rooms_x, b.rooms_y};
}

}  // namespace

const SettingsTable<BuildingSpec>& BuildingSettings() {
  static const SettingsTable<BuildingSpec> table{
      "building",
      "/buildings/<i>",
      "A building: an ns-3 Building, a box on the ground, inside the venue and apart from the "
      "others.",
      {{"name", &BuildingSpec::name, NoRange(), "its name (\"building<i>\", counting from 0)"},
       {"x",
        CustomValue<BuildingSpec>{ReadX, XJson, "[min, max]"},
        NoRange(),
        "its x extent",
        "m",
        {},
        "[xmin, xmax]"},
       {"y",
        CustomValue<BuildingSpec>{ReadY, YJson, "[min, max]"},
        NoRange(),
        "its y extent",
        "m",
        {},
        "[ymin, ymax]"},
       {"height", &BuildingSpec::height, Positive(), "its height", "m", {}, ""},
       {"floors", &BuildingSpec::floors, Integers(1, 200), "floors (ns-3's NFloors)"},
       {"rooms", CustomValue<BuildingSpec>{ReadRooms, RoomsJson, "[rooms_x, rooms_y]"}, NoRange(),
        "rooms per floor along x and y (ns-3's NRoomsX, NRoomsY)"},
       {"type",
        &BuildingSpec::type,
        NoRange(),
        "ns-3's Building::BuildingType",
        "",
        {"residential", "office", "commercial"}},
       {"walls",
        &BuildingSpec::walls,
        NoRange(),
        "ns-3's Building::ExtWallsType: the loss through its walls",
        "",
        {"wood", "concrete_with_windows", "concrete_without_windows", "stone_blocks"}}}};
  return table;
}

}  // namespace rlpos
