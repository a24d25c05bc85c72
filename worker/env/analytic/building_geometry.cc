#include "worker/env/analytic/building_geometry.h"

#include <cmath>

namespace rlpos {

BuildingGeometry::BuildingGeometry(const std::vector<BuildingSpec>& buildings) {
  for (const auto& building : buildings) {
    CentredBox box;
    box.bounds = building.Footprint3d();
    const Box& b = box.bounds;
    // Half sizes first, then the centre from the low corner: the order ns-3's Box uses.
    box.half = {0.5 * (b.xmax - b.xmin), 0.5 * (b.ymax - b.ymin), 0.5 * (b.zmax - b.zmin)};
    box.centre = {b.xmin + box.half.x, b.ymin + box.half.y, b.zmin + box.half.z};
    boxes_.push_back(box);
  }
}

int BuildingGeometry::BuildingAt(const Vec3& p) const {
  for (std::size_t k = 0; k < boxes_.size(); ++k) {
    if (boxes_[k].bounds.Contains(p))
      return static_cast<int>(k);
  }
  return -1;
}

// Separating axes of a segment and an axis-aligned box (e.g. Ericson, Real-Time Collision
// Detection, 5.3.3): in the box's frame, the segment is its midpoint m and half extent d; they
// are apart iff one of the box's three axes or one of the three products of d with an axis
// separates them. Touching counts as meeting (strict comparisons).
bool BuildingGeometry::SegmentMeets(const CentredBox& box, const Vec3& a, const Vec3& b) {
  const Vec3& c = box.centre;
  const Vec3& h = box.half;
  const Vec3 ra{a.x - c.x, a.y - c.y, a.z - c.z};
  const Vec3 rb{b.x - c.x, b.y - c.y, b.z - c.z};
  const Vec3 m{0.5 * (ra.x + rb.x), 0.5 * (ra.y + rb.y), 0.5 * (ra.z + rb.z)};
  const Vec3 d{ra.x - m.x, ra.y - m.y, ra.z - m.z};
  const Vec3 e{std::abs(d.x), std::abs(d.y), std::abs(d.z)};
  if (std::abs(m.x) > h.x + e.x || std::abs(m.y) > h.y + e.y || std::abs(m.z) > h.z + e.z)
    return false;
  if (std::abs(m.y * d.z - m.z * d.y) > h.y * e.z + h.z * e.y)
    return false;
  if (std::abs(m.x * d.z - m.z * d.x) > h.x * e.z + h.z * e.x)
    return false;
  if (std::abs(m.x * d.y - m.y * d.x) > h.x * e.y + h.y * e.x)
    return false;
  return true;
}

bool BuildingGeometry::Los(const Vec3& a, const Vec3& b) const {
  const int in_a = BuildingAt(a);
  const int in_b = BuildingAt(b);
  if (in_a >= 0 || in_b >= 0)
    return in_a == in_b;
  for (const auto& box : boxes_) {
    if (SegmentMeets(box, a, b))
      return false;
  }
  return true;
}

}  // namespace rlpos
