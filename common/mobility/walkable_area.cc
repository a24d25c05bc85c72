#include "common/mobility/walkable_area.h"

#include <algorithm>

#include "common/scenario/building_obstacles.h"

namespace rlpos {
namespace {

bool InBounds(const Bounds2& b, double x, double y) {
  return x >= b.xmin && x <= b.xmax && y >= b.ymin && y <= b.ymax;
}

bool LegMayMeet(const Bounds2& b, const Vec3& p, const Vec3& q) {
  return std::max(p.x, q.x) >= b.xmin && std::min(p.x, q.x) <= b.xmax &&
         std::max(p.y, q.y) >= b.ymin && std::min(p.y, q.y) <= b.ymax;
}

}  // namespace

WalkableArea::WalkableArea(const Scenario& scenario)
    : width_(scenario.venue.width), depth_(scenario.venue.depth) {
  for (const auto& b : scenario.buildings) {
    Shape shape{GroundShape(b), {}};
    shape.bounds = BoundsOf(shape.ground.outer);
    shapes_.push_back(std::move(shape));
  }
}

bool WalkableArea::Contains(double x, double y) const {
  if (x < 0 || x > width_ || y < 0 || y > depth_)
    return false;
  return std::none_of(shapes_.begin(), shapes_.end(), [&](const Shape& s) {
    return InBounds(s.bounds, x, y) && rlpos::Contains(s.ground, {x, y});
  });
}

bool WalkableArea::LegIsClear(const Vec3& a, const Vec3& b) const {
  // The venue is convex: both ends in it keep the leg in it.
  if (!Contains(a.x, a.y) || !Contains(b.x, b.y))
    return false;
  return std::none_of(shapes_.begin(), shapes_.end(), [&](const Shape& s) {
    return LegMayMeet(s.bounds, a, b) && SegmentMeets(s.ground, {a.x, a.y}, {b.x, b.y});
  });
}

}  // namespace rlpos
