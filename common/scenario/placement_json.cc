#include "common/scenario/placement_json.h"

namespace rlpos {

nlohmann::json PlacementJson(const Placement& placement) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec3& p : placement)
    out.push_back({p.x, p.y, p.z});
  return out;
}

}  // namespace rlpos
