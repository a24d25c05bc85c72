#include "common/geometry/footprint.h"

#include <algorithm>
#include <cmath>

#include "common/geometry/planar.h"

namespace rlpos {

using planar::Next;

double SignedArea(const Ring& ring) {
  // The shoelace formula about the first vertex, which keeps the products small far from the
  // origin.
  double twice = 0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i)
    twice += planar::Cross(ring[0], ring[i], ring[i + 1]);
  return 0.5 * twice;
}

double Area(const Footprint& footprint) {
  double area = std::abs(SignedArea(footprint.outer));
  for (const auto& hole : footprint.holes)
    area -= std::abs(SignedArea(hole));
  return area;
}

Bounds2 BoundsOf(const Ring& ring) {
  if (ring.empty())
    return {};
  Bounds2 b{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
  for (const auto& p : ring) {
    b.xmin = std::min(b.xmin, p.x);
    b.ymin = std::min(b.ymin, p.y);
    b.xmax = std::max(b.xmax, p.x);
    b.ymax = std::max(b.ymax, p.y);
  }
  return b;
}

bool Contains(const Footprint& footprint, const Point2& p) {
  return planar::FootprintSide(footprint, p) != planar::Side::kOutside;
}

// The closed segment meets the closed region iff an end lies in it or the segment meets its
// boundary: a segment that enters the region crosses or touches an edge on the way. The edges
// first: most are apart from the segment at the first comparisons, while the end's test walks
// every edge in full.
bool SegmentMeets(const Footprint& footprint, const Point2& a, const Point2& b) {
  auto meets_ring = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (planar::SegmentsMeet(a, b, ring[i], Next(ring, i)))
        return true;
    }
    return false;
  };
  if (meets_ring(footprint.outer) ||
      std::any_of(footprint.holes.begin(), footprint.holes.end(), meets_ring))
    return true;
  return Contains(footprint, a);
}

bool HeightSlice(const Vec3& a, const Vec3& b, double zmin, double zmax, Point2& from, Point2& to) {
  from = {a.x, a.y};
  to = {b.x, b.y};
  if (a.z == b.z)  // level: wholly in the height range or wholly out
    return a.z >= zmin && a.z <= zmax;
  // The part between the two heights, as parameters along the segment.
  const double dz = b.z - a.z;
  double t0 = (zmin - a.z) / dz, t1 = (zmax - a.z) / dz;
  if (t0 > t1)
    std::swap(t0, t1);
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, 1.0);
  if (t0 > t1)
    return false;
  auto at = [&](double t) -> Point2 {
    if (t == 0.0)
      return {a.x, a.y};
    if (t == 1.0)
      return {b.x, b.y};
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  };
  from = at(t0);
  to = at(t1);
  return true;
}

bool SegmentMeetsPrism(const Footprint& footprint, double zmin, double zmax, const Vec3& a,
                       const Vec3& b) {
  if (a.x == b.x && a.y == b.y) {  // vertical (or a point): its column against the prism
    return std::max(a.z, b.z) >= zmin && std::min(a.z, b.z) <= zmax &&
           Contains(footprint, {a.x, a.y});
  }
  Point2 from, to;
  return HeightSlice(a, b, zmin, zmax, from, to) && SegmentMeets(footprint, from, to);
}

}  // namespace rlpos
