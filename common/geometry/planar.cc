#include "common/geometry/planar.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rlpos {
namespace planar {

// The box first: it rules out most pairs before the products are formed.
bool OnSegment(const Point2& p, const Point2& a, const Point2& b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y) && Orient(a, b, p) == 0;
}

bool SegmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  // Apart in x or y: the common case, and it keeps rounding out of far-apart pairs.
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;
  const int o1 = Orient(a, b, c), o2 = Orient(a, b, d);
  const int o3 = Orient(c, d, a), o4 = Orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0)
    return true;
  return (o1 == 0 && OnSegment(c, a, b)) || (o2 == 0 && OnSegment(d, a, b)) ||
         (o3 == 0 && OnSegment(a, c, d)) || (o4 == 0 && OnSegment(b, c, d));
}

double SegmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Crossing number along the ray to +x, with the boundary found first. Whether an edge crosses
// the ray is decided by orientation, not by a computed crossing x, so that a point is never
// both on an edge and inside by a different rounding.
Side RingSide(const Ring& ring, const Point2& p) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = Next(ring, i);
    if (OnSegment(p, a, b))
      return Side::kBoundary;
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = Orient(a, b, p);
      if (b.y > a.y ? o > 0 : o < 0)
        inside = !inside;
    }
  }
  return inside ? Side::kInside : Side::kOutside;
}

Side FootprintSide(const Footprint& footprint, const Point2& p) {
  Side side = RingSide(footprint.outer, p);
  if (side == Side::kOutside)
    return side;
  for (const auto& hole : footprint.holes) {
    const Side in_hole = RingSide(hole, p);
    if (in_hole == Side::kInside)
      return Side::kOutside;
    if (in_hole == Side::kBoundary)
      side = Side::kBoundary;
  }
  return side;
}

double BoundaryDistance(const Footprint& footprint, const Point2& p) {
  double best = std::numeric_limits<double>::infinity();
  auto scan = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      best = std::min(best, SegmentDistance(p, ring[i], Next(ring, i)));
  };
  scan(footprint.outer);
  for (const auto& hole : footprint.holes)
    scan(hole);
  return best;
}

namespace {

// The parameters along [a, b] (in (0, 1)) where it meets the segment [c, d]: a crossing or a
// touch, or the ends of a shared stretch.
void AppendMeetings(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                    std::vector<double>& ts) {
  if (!SegmentsMeet(a, b, c, d))
    return;
  const double ca = Cross(c, d, a), cb = Cross(c, d, b);
  if (ca != cb) {  // not parallel: one point
    ts.push_back(ca / (ca - cb));
    return;
  }
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  if (length2 == 0)
    return;
  for (const Point2& q : {c, d})
    ts.push_back(((q.x - a.x) * dx + (q.y - a.y) * dy) / length2);
}

}  // namespace

void AppendPieceMidpoints(const Point2& a, const Point2& b, const Footprint& other,
                          std::vector<Point2>& out) {
  std::vector<double> ts{0.0, 1.0};
  auto scan = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      AppendMeetings(a, b, ring[i], Next(ring, i), ts);
  };
  scan(other.outer);
  for (const auto& hole : other.holes)
    scan(hole);
  for (double& t : ts)
    t = std::clamp(t, 0.0, 1.0);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  out.push_back(a);
  out.push_back(b);
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t = 0.5 * (ts[k] + ts[k + 1]);
    out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
  }
}

}  // namespace planar
}  // namespace rlpos
