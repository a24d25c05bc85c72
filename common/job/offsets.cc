#include "common/job/offsets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/scenario/building_obstacles.h"

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

// The same for a footprint between two heights: the ray's stretch within the heights, then the
// first point of that stretch on the ground shape (its start, or where it crosses an edge).
double EntryDistance(const Vec3& origin, const Vec3& u, const Solid& solid) {
  if (solid.IsBox())
    return EntryDistance(origin, u, solid.box);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double enter = 0.0, leave = kInf;
  if (u.z == 0.0) {
    if (origin.z < solid.box.zmin || origin.z > solid.box.zmax)
      return kInf;
  } else {
    double t0 = (solid.box.zmin - origin.z) / u.z, t1 = (solid.box.zmax - origin.z) / u.z;
    if (t0 > t1)
      std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave)
      return kInf;
  }
  const Point2 start{origin.x + enter * u.x, origin.y + enter * u.y};
  if (Contains(solid.footprint, start))
    return enter;
  if (u.x == 0.0 && u.y == 0.0)
    return kInf;  // vertical, and not over the shape
  double first = kInf;
  const auto cross_edges = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % ring.size()];
      // origin + t u = a + s (b - a), in the plane: Cramer's rule.
      const double ex = b.x - a.x, ey = b.y - a.y;
      const double det = u.x * (-ey) - u.y * (-ex);
      if (det == 0.0)
        continue;  // parallel: an edge along the ray is met at its end, by the next edge
      const double rx = a.x - origin.x, ry = a.y - origin.y;
      const double t = (rx * (-ey) - ry * (-ex)) / det;
      const double s = (u.x * ry - u.y * rx) / det;
      if (s >= 0.0 && s <= 1.0 && t >= enter && t <= leave)
        first = std::min(first, t);
    }
  };
  cross_edges(solid.footprint.outer);
  for (const Ring& hole : solid.footprint.holes)
    cross_edges(hole);
  return first;
}

bool Holds(const Solid& solid, const Vec3& p) {
  if (solid.IsBox())
    return solid.box.Contains(p);
  return p.z >= solid.box.zmin && p.z <= solid.box.zmax && Contains(solid.footprint, {p.x, p.y});
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
    g.obstacles.push_back(BuildingSolid(b));
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
    if (Holds(obstacle, center))
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
