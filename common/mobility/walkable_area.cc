#include "common/mobility/walkable_area.h"

#include <algorithm>

namespace rlpos {
namespace {

// Whether the segment a -> b meets the closed rectangle (Liang-Barsky clipping: the segment's
// parameter interval inside each slab, intersected).
bool SegmentMeetsRectangle(double ax, double ay, double bx, double by, double xmin, double xmax,
                           double ymin, double ymax) {
  double t0 = 0.0, t1 = 1.0;
  const double d[2] = {bx - ax, by - ay};
  const double start[2] = {ax, ay};
  const double lo[2] = {xmin, ymin};
  const double hi[2] = {xmax, ymax};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (start[k] < lo[k] || start[k] > hi[k])
        return false;
      continue;
    }
    double ta = (lo[k] - start[k]) / d[k];
    double tb = (hi[k] - start[k]) / d[k];
    if (ta > tb)
      std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1)
      return false;
  }
  return true;
}

}  // namespace

WalkableArea::WalkableArea(const Scenario& scenario)
    : width_(scenario.venue.width), depth_(scenario.venue.depth) {
  for (const auto& b : scenario.buildings)
    footprints_.push_back({b.xmin, b.xmax, b.ymin, b.ymax});
}

bool WalkableArea::Contains(double x, double y) const {
  if (x < 0 || x > width_ || y < 0 || y > depth_)
    return false;
  return std::none_of(footprints_.begin(), footprints_.end(), [&](const Rectangle& r) {
    return x >= r.xmin && x <= r.xmax && y >= r.ymin && y <= r.ymax;
  });
}

bool WalkableArea::LegIsClear(const Vec3& a, const Vec3& b) const {
  // The venue is convex: both ends in it keep the leg in it.
  if (!Contains(a.x, a.y) || !Contains(b.x, b.y))
    return false;
  return std::none_of(footprints_.begin(), footprints_.end(), [&](const Rectangle& r) {
    return SegmentMeetsRectangle(a.x, a.y, b.x, b.y, r.xmin, r.xmax, r.ymin, r.ymax);
  });
}

}  // namespace rlpos
