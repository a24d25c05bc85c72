#include "worker/map/map_shapes.h"

#include <algorithm>
#include <cmath>

namespace rlpos::map {
namespace {

// A stretch of a line inside the shape, between two of its crossings with the shape's edges.
struct Stretch {
  double from = 0, to = 0;
};

// The inside stretches of the line y = c (horizontal) or x = c, from its crossings with every
// ring's edges. An edge counts from its lower end up to, not at, its upper end: the crossings pair
// up even-odd, as the map fills the shape.
std::vector<Stretch> Stretches(const Footprint& shape, bool horizontal, double c) {
  std::vector<double> crossings;
  const auto cross = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % ring.size()];
      const double a_across = horizontal ? a.y : a.x, b_across = horizontal ? b.y : b.x;
      if ((a_across > c) == (b_across > c))
        continue;
      const double a_along = horizontal ? a.x : a.y, b_along = horizontal ? b.x : b.y;
      crossings.push_back(a_along + (c - a_across) * (b_along - a_along) / (b_across - a_across));
    }
  };
  cross(shape.outer);
  for (const Ring& hole : shape.holes)
    cross(hole);
  std::sort(crossings.begin(), crossings.end());
  std::vector<Stretch> stretches;
  for (std::size_t i = 0; i + 1 < crossings.size(); i += 2)
    stretches.push_back({crossings[i], crossings[i + 1]});
  return stretches;
}

// `p` moved to the middle of the inside stretch through it along the other axis: the middle of
// a horizontal stretch, centred up and down too, sits mid-way across a wing of the shape.
Point2 CentredAcross(const Footprint& shape, bool horizontal_stretch, Point2 p) {
  const double along = horizontal_stretch ? p.y : p.x;
  for (const Stretch& s : Stretches(shape, !horizontal_stretch, horizontal_stretch ? p.x : p.y)) {
    if (s.from <= along && along <= s.to) {
      (horizontal_stretch ? p.y : p.x) = (s.from + s.to) / 2;
      break;
    }
  }
  return p;
}

// The centroid of the outer ring less its holes (each ring's first moments, signs made
// positive, the holes' taken away).
Point2 Centroid(const Footprint& shape) {
  double area = 0, mx = 0, my = 0;
  const auto add = [&](const Ring& ring, double sign) {
    double a = 0, x = 0, y = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& p = ring[i];
      const Point2& q = ring[(i + 1) % ring.size()];
      const double cross = p.x * q.y - q.x * p.y;
      a += cross / 2;
      x += (p.x + q.x) * cross / 6;
      y += (p.y + q.y) * cross / 6;
    }
    const double s = a < 0 ? -sign : sign;
    area += s * a, mx += s * x, my += s * y;
  };
  add(shape.outer, 1.0);
  for (const Ring& hole : shape.holes)
    add(hole, -1.0);
  if (area <= 0)
    return shape.outer.empty() ? Point2{} : shape.outer.front();
  return {mx / area, my / area};
}

}  // namespace

std::vector<Point2> LabelPoints(const BuildingSpec& b) {
  const Point2 centre{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2};
  if (!b.HasFootprint())
    return {centre};
  const Footprint& shape = b.footprint;
  std::vector<Point2> points;
  for (const Point2& p : {centre, Centroid(shape)}) {
    if (Contains(shape, p))
      points.push_back(p);
  }
  struct Candidate {
    double length;
    Point2 at;
  };
  std::vector<Candidate> candidates;
  for (bool horizontal : {true, false}) {
    const double lo = horizontal ? b.ymin : b.xmin, hi = horizontal ? b.ymax : b.xmax;
    for (int k = 1; k < 8; ++k) {
      const double c = lo + (hi - lo) * k / 8.0;
      for (const Stretch& s : Stretches(shape, horizontal, c)) {
        const double mid = (s.from + s.to) / 2;
        const Point2 p = horizontal ? Point2{mid, c} : Point2{c, mid};
        candidates.push_back({s.to - s.from, CentredAcross(shape, horizontal, p)});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& c) { return a.length > c.length; });
  for (const Candidate& c : candidates) {
    if (Contains(shape, c.at))
      points.push_back(c.at);
  }
  if (points.empty())
    points.push_back(centre);  // no inside stretch found: a sliver; the label goes beside it
  return points;
}

bool RectangleInside(const Footprint& shape, const Bounds2& r) {
  const Point2 corners[] = {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
  for (const Point2& corner : corners) {
    if (!Contains(shape, corner))
      return false;
  }
  // With its corners inside, the rectangle is in the shape unless an edge (a notch, a hole) cuts
  // into it: tested against the rectangle shrunk by a hair, so that an edge along a side is fine.
  constexpr double kHair = 1e-6;  // m
  if (r.xmax - r.xmin <= 2 * kHair || r.ymax - r.ymin <= 2 * kHair)
    return true;
  const Footprint inner{{{r.xmin + kHair, r.ymin + kHair},
                         {r.xmax - kHair, r.ymin + kHair},
                         {r.xmax - kHair, r.ymax - kHair},
                         {r.xmin + kHair, r.ymax - kHair}},
                        {}};
  const auto cuts = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (SegmentMeets(inner, ring[i], ring[(i + 1) % ring.size()]))
        return true;
    }
    return false;
  };
  if (cuts(shape.outer))
    return false;
  for (const Ring& hole : shape.holes) {
    if (cuts(hole))
      return false;
  }
  return true;
}

}  // namespace rlpos::map
