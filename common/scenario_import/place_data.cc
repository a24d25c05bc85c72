#include "common/scenario_import/place_data.h"

namespace rlpos {

const std::vector<std::string>& PlaceTagKeys() {
  static const std::vector<std::string> keys{
      "name",       "building",           "building:part", "height", "building:levels",
      "min_height", "building:min_level", "roof:height"};
  return keys;
}

BuildingRole RoleOf(const char* building, const char* building_part) {
  if (building_part != nullptr && std::string(building_part) != "no")
    return BuildingRole::kPart;
  if (building != nullptr && std::string(building) != "no")
    return BuildingRole::kOutline;
  return BuildingRole::kNone;
}

}  // namespace rlpos
