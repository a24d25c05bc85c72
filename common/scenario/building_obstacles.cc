#include "common/scenario/building_obstacles.h"

namespace rlpos {

Footprint GroundShape(const BuildingSpec& b) {
  if (b.HasFootprint())
    return b.footprint;
  return {{{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}}, {}};
}

Solid BuildingSolid(const BuildingSpec& b) {
  if (b.HasFootprint())
    return Solid::Prism(b.footprint, b.min_height, b.height);
  return Solid::OfBox(b.Footprint3d());
}

Obstacles BuildingObstacles(const std::vector<BuildingSpec>& buildings) {
  std::vector<Solid> solids;
  solids.reserve(buildings.size());
  for (const auto& b : buildings)
    solids.push_back(BuildingSolid(b));
  return Obstacles(std::move(solids));
}

bool BuildingHolds(const BuildingSpec& b, const Vec3& p) {
  if (!b.Footprint3d().Contains(p))
    return false;
  return !b.HasFootprint() || Contains(b.footprint, {p.x, p.y});
}

bool GroundShapeHolds(const BuildingSpec& b, double x, double y) {
  if (!(x >= b.xmin && x <= b.xmax && y >= b.ymin && y <= b.ymax))
    return false;
  return !b.HasFootprint() || Contains(b.footprint, {x, y});
}

}  // namespace rlpos
