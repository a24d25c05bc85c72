#include "common/scenario_generator/los_geometry.h"

#include <cmath>

namespace rlpos {

// The separating-axis test of a segment against an axis-aligned box: with the box centred at
// the origin (half sizes h) and the segment given by its midpoint m and half extent e, the two
// are apart exactly when one of six axes separates them: the box's three axes and the cross
// products of the segment's direction with each of them.
bool SegmentMeetsBox(const Vec3& a, const Vec3& b, const Box& box) {
  const double hx = (box.xmax - box.xmin) / 2, hy = (box.ymax - box.ymin) / 2,
               hz = (box.zmax - box.zmin) / 2;
  const double cx = box.xmin + hx, cy = box.ymin + hy, cz = box.zmin + hz;
  const double ex = (b.x - a.x) / 2, ey = (b.y - a.y) / 2, ez = (b.z - a.z) / 2;
  const double mx = a.x + ex - cx, my = a.y + ey - cy, mz = a.z + ez - cz;
  const double ax = std::fabs(ex), ay = std::fabs(ey), az = std::fabs(ez);
  if (std::fabs(mx) > hx + ax || std::fabs(my) > hy + ay || std::fabs(mz) > hz + az)
    return false;
  if (std::fabs(my * ez - mz * ey) > hy * az + hz * ay)
    return false;
  if (std::fabs(mx * ez - mz * ex) > hx * az + hz * ax)
    return false;
  if (std::fabs(mx * ey - my * ex) > hx * ay + hy * ax)
    return false;
  return true;
}

bool LinkBlocked(const std::vector<BuildingSpec>& buildings, const Vec3& a, const Vec3& b) {
  for (const auto& building : buildings) {
    if (SegmentMeetsBox(a, b, building.Footprint3d()))
      return true;
  }
  return false;
}

int UesHiddenFromAll(const Scenario& scenario, const Placement& placement) {
  int hidden = 0;
  for (const auto& ue : scenario.ues) {
    bool seen = false;
    for (const auto& uav : placement)
      seen = seen || !LinkBlocked(scenario.buildings, ue.position, uav);
    hidden += seen ? 0 : 1;
  }
  return hidden;
}

}  // namespace rlpos
