#include "common/geometry/obstacles.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rlpos {

Solid Solid::OfBox(const Box& box) {
  return {box, {}};
}

Solid Solid::Prism(Footprint footprint, double zmin, double zmax) {
  const Bounds2 b = BoundsOf(footprint.outer);
  return {{b.xmin, b.xmax, b.ymin, b.ymax, zmin, zmax}, std::move(footprint)};
}

Obstacles::Obstacles(std::vector<Solid> solids) {
  std::vector<Bounds2> bounds;
  for (auto& solid : solids) {
    Entry e{std::move(solid), {}, {}, {}};
    const Box& b = e.solid.box;
    e.rings = BoundsOf(e.solid.footprint.outer);
    for (const Ring& hole : e.solid.footprint.holes) {
      const Bounds2 h = BoundsOf(hole);
      e.rings = {std::min(e.rings.xmin, h.xmin), std::min(e.rings.ymin, h.ymin),
                 std::max(e.rings.xmax, h.xmax), std::max(e.rings.ymax, h.ymax)};
    }
    // Half sizes first, then the centre from the low corner: the order ns-3's Box uses.
    e.half = {0.5 * (b.xmax - b.xmin), 0.5 * (b.ymax - b.ymin), 0.5 * (b.zmax - b.zmin)};
    e.centre = {b.xmin + e.half.x, b.ymin + e.half.y, b.zmin + e.half.z};
    bounds.push_back({b.xmin, b.ymin, b.xmax, b.ymax});
    solids_.push_back(std::move(e));
  }
  grid_ = SolidGrid(bounds);
}

bool Obstacles::Holds(std::size_t i, const Vec3& p) const {
  const Solid& s = solids_[i].solid;
  if (!s.box.Contains(p))
    return false;
  return s.IsBox() || Contains(s.footprint, {p.x, p.y});
}

bool Obstacles::HoldsGround(std::size_t i, double x, double y) const {
  const Solid& s = solids_[i].solid;
  if (!(x >= s.box.xmin && x <= s.box.xmax && y >= s.box.ymin && y <= s.box.ymax))
    return false;
  return s.IsBox() || Contains(s.footprint, {x, y});
}

// Separating axes of a segment and an axis-aligned box (e.g. Ericson, Real-Time Collision
// Detection, 5.3.3): in the box's frame, the segment is its midpoint m and half extent d; they
// are apart iff one of the box's three axes or one of the three products of d with an axis
// separates them. Touching counts as meeting (strict comparisons). The same operations in the
// same order as worker/env/analytic/building_geometry.cc, which matches ns-3 bit for bit.
bool Obstacles::BoxMeets(const Entry& box, const Vec3& a, const Vec3& b) {
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

bool Obstacles::Meets(std::size_t i, const Vec3& a, const Vec3& b) const {
  const Entry& e = solids_[i];
  if (e.solid.IsBox())
    return BoxMeets(e, a, b);
  // Apart from the bounding box (widened past any rounding of the cut below): apart.
  const Box& box = e.solid.box;
  const double pad = 1e-9 * (1.0 + std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x),
                                             std::abs(b.y), std::abs(box.xmin), std::abs(box.xmax),
                                             std::abs(box.ymin), std::abs(box.ymax)}));
  if (std::max(a.x, b.x) < box.xmin - pad || std::min(a.x, b.x) > box.xmax + pad ||
      std::max(a.y, b.y) < box.ymin - pad || std::min(a.y, b.y) > box.ymax + pad ||
      std::max(a.z, b.z) < box.zmin || std::min(a.z, b.z) > box.zmax)
    return false;
  if (a.x == b.x && a.y == b.y)
    return SegmentMeetsPrism(e.solid.footprint, box.zmin, box.zmax, a, b);
  // The same for the part within the prism's heights, which a segment from the street to the
  // sky leaves far shorter: apart from the rings' bounds by more than rounding, it meets no edge
  // and its end lies outside, so the plane's test would say "apart" after walking every edge.
  Point2 from, to;
  if (!HeightSlice(a, b, box.zmin, box.zmax, from, to))
    return false;
  const Bounds2& r = e.rings;
  if (std::max(from.x, to.x) < r.xmin - pad || std::min(from.x, to.x) > r.xmax + pad ||
      std::max(from.y, to.y) < r.ymin - pad || std::min(from.y, to.y) > r.ymax + pad)
    return false;
  return SegmentMeets(e.solid.footprint, from, to);
}

int Obstacles::SolidAt(const Vec3& p) const {
  const auto [begin, end] = grid_.At(p.x, p.y);
  for (const int* i = begin; i != end; ++i) {
    if (Holds(static_cast<std::size_t>(*i), p))
      return *i;
  }
  return -1;
}

int Obstacles::FootprintAt(double x, double y) const {
  const auto [begin, end] = grid_.At(x, y);
  for (const int* i = begin; i != end; ++i) {
    if (HoldsGround(static_cast<std::size_t>(*i), x, y))
      return *i;
  }
  return -1;
}

bool Obstacles::Blocked(const Vec3& a, const Vec3& b) const {
  // The cells from a's end, stopping at the first solid met: no list, no allocation.
  return grid_.AnyAlong({a.x, a.y}, {b.x, b.y},
                        [&](int i) { return Meets(static_cast<std::size_t>(i), a, b); });
}

bool Obstacles::Los(const Vec3& a, const Vec3& b) const {
  const int in_a = SolidAt(a);
  const int in_b = SolidAt(b);
  if (in_a >= 0 || in_b >= 0)
    return in_a == in_b;
  return !Blocked(a, b);
}

}  // namespace rlpos
