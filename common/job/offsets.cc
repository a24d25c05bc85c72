#include "common/job/offsets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rlpos {
namespace {

Vec3 Clamp(const Vec3& p, const Box& b) {
  return {std::clamp(p.x, b.xmin, b.xmax), std::clamp(p.y, b.ymin, b.ymax),
          std::clamp(p.z, b.zmin, b.zmax)};
}

// Distance along the unit ray (origin, u) at which it enters the closed box, or +inf when the
// ray misses it (slab method).
double EntryDistance(const Vec3& origin, const Vec3& u, const Box& b) {
  const double o[3] = {origin.x, origin.y, origin.z};
  const double d[3] = {u.x, u.y, u.z};
  const double lo[3] = {b.xmin, b.ymin, b.zmin};
  const double hi[3] = {b.xmax, b.ymax, b.zmax};
  double enter = 0.0;
  double leave = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a])
        return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = (lo[a] - o[a]) / d[a];
    double t1 = (hi[a] - o[a]) / d[a];
    if (t0 > t1)
      std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave ? enter : std::numeric_limits<double>::infinity();
}

}  // namespace

OffsetGeometry OffsetGeometryOf(const Scenario& s) {
  OffsetGeometry g;
  const Box venue{0.0, s.venue.width, 0.0, s.venue.depth, 0.0, s.venue.height};
  const Box& zone = s.uavs.front().zone;  // offsets move one UAV
  g.bounds = {std::max(zone.xmin, venue.xmin), std::min(zone.xmax, venue.xmax),
              std::max(zone.ymin, venue.ymin), std::min(zone.ymax, venue.ymax),
              std::max(zone.zmin, venue.zmin), std::min(zone.zmax, venue.zmax)};
  for (const auto& b : s.buildings)
    g.obstacles.push_back(b.Footprint3d());
  return g;
}

Vec3 OffsetDirection(int k) {
  switch (k) {
    case 1:
      return {1, 0, 0};
    case 2:
      return {-1, 0, 0};
    case 3:
      return {0, 1, 0};
    case 4:
      return {0, -1, 0};
    case 5:
      return {0, 0, 1};
    default:
      throw std::out_of_range("offset position " + std::to_string(k) + " is not in 1..5");
  }
}

Vec3 OffsetPosition(const Vec3& center, int k, const OffsetGeometry& geometry, double distance) {
  const Vec3 d = OffsetDirection(k);
  const Vec3 target =
      Clamp({center.x + distance * d.x, center.y + distance * d.y, center.z + distance * d.z},
            geometry.bounds);
  const Vec3 step{target.x - center.x, target.y - center.y, target.z - center.z};
  const double length = std::sqrt(step.x * step.x + step.y * step.y + step.z * step.z);
  if (length == 0.0)
    return target;
  const Vec3 u{step.x / length, step.y / length, step.z / length};
  double reach = length;
  for (const auto& obstacle : geometry.obstacles) {
    // A centre inside a building is the agent's problem, not something to route around.
    if (obstacle.Contains(center))
      continue;
    const double entry = EntryDistance(center, u, obstacle);
    if (entry <= length)
      reach = std::min(reach, std::max(0.0, entry - kObstacleMargin));
  }
  return {center.x + reach * u.x, center.y + reach * u.y, center.z + reach * u.z};
}

std::vector<Vec3> OffsetPositions(const Vec3& center, const OffsetGeometry& geometry,
                                  double distance) {
  std::vector<Vec3> out;
  for (int k = 1; k <= kOffsetCount; ++k) {
    out.push_back(OffsetPosition(center, k, geometry, distance));
  }
  return out;
}

}  // namespace rlpos
