#pragma once
// The plane's primitives the footprint functions share: orientation, closed segment tests, a
// point against a ring. Plain double arithmetic, the same on every machine (no fused
// multiply-add is asked for), so a scenario's answers repeat bit for bit; points within a few
// ulps of a line may be classed on either side of it.
#include <cstddef>

#include "common/geometry/footprint.h"

namespace rlpos {
namespace planar {

// Twice the signed area of the triangle a, b, c: > 0 when c lies left of a -> b.
inline double Cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
inline int Orient(const Point2& a, const Point2& b, const Point2& c) {
  const double v = Cross(a, b, c);
  return (v > 0) - (v < 0);
}
inline bool SamePoint(const Point2& a, const Point2& b) {
  return a.x == b.x && a.y == b.y;
}
// Vertex i + 1 of `ring`, wrapping round.
inline const Point2& Next(const Ring& ring, std::size_t i) {
  return ring[i + 1 == ring.size() ? 0 : i + 1];
}

// `p` lies on the closed segment [a, b].
bool OnSegment(const Point2& p, const Point2& a, const Point2& b);
// The closed segments [a, b] and [c, d] share a point.
bool SegmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
// The distance (m) from `p` to the closed segment [a, b].
double SegmentDistance(const Point2& p, const Point2& a, const Point2& b);

enum class Side { kOutside, kBoundary, kInside };
// Where `p` lies against the region a simple ring bounds.
Side RingSide(const Ring& ring, const Point2& p);
// Where `p` lies against a footprint's region (inside: in the outer ring's interior and off
// every hole's closed region).
Side FootprintSide(const Footprint& footprint, const Point2& p);
// The distance (m) from `p` to the nearest edge of any of the footprint's rings.
double BoundaryDistance(const Footprint& footprint, const Point2& p);

// Points of the segment [a, b] that tell how it lies against the boundary of `other`: its
// endpoints and the midpoints of the pieces it is cut into where it meets that boundary. Each
// piece lies wholly inside, on or outside `other`, so its midpoint speaks for it.
void AppendPieceMidpoints(const Point2& a, const Point2& b, const Footprint& other,
                          std::vector<Point2>& out);

}  // namespace planar
}  // namespace rlpos
