// Why a ring or a footprint is not a valid polygon.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/geometry/footprint.h"
#include "common/geometry/planar.h"

namespace rlpos {
namespace {

using planar::Next;

std::string Pair(const char* what, std::size_t i, std::size_t j, const char* verb) {
  return std::string(what) + " " + std::to_string(i) + " and " + std::to_string(j) + " " + verb;
}

// Two vertices at the same point: the smallest pair of indices, or "".
std::string RepeatedVertex(const Ring& ring, std::size_t& distinct) {
  std::vector<std::size_t> order(ring.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](std::size_t a, std::size_t b) {
    return ring[a].x != ring[b].x   ? ring[a].x < ring[b].x
           : ring[a].y != ring[b].y ? ring[a].y < ring[b].y
                                    : a < b;
  };
  std::sort(order.begin(), order.end(), less);
  distinct = ring.empty() ? 0 : 1;
  std::size_t best_i = ring.size(), best_j = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (!planar::SamePoint(ring[order[k - 1]], ring[order[k]])) {
      ++distinct;
      continue;
    }
    // Sorted by index within a point: the group's first two are its smallest pair.
    const bool group_start = k == 1 || !planar::SamePoint(ring[order[k - 2]], ring[order[k]]);
    if (group_start && order[k - 1] < best_i) {
      best_i = order[k - 1];
      best_j = order[k];
    }
  }
  return best_i < ring.size() ? Pair("vertices", best_i, best_j, "coincide") : "";
}

// An edge that doubles back along the one before it (a spike of zero width).
std::string FoldedEdge(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& prev = ring[(k + n - 1) % n];
    const Point2& at = ring[k];
    const Point2& next = Next(ring, k);
    const double dot = (prev.x - at.x) * (next.x - at.x) + (prev.y - at.y) * (next.y - at.y);
    if (planar::Orient(prev, at, next) == 0 && dot > 0) {
      const std::size_t before = (k + n - 1) % n;
      return Pair("edges", std::min(before, k), std::max(before, k), "overlap");
    }
  }
  return "";
}

// Two edges that are not neighbours and meet: a sweep over the edges sorted by their lowest x
// compares only those whose x ranges overlap. The smallest pair of indices is reported.
std::string MeetingEdges(const Ring& ring) {
  const std::size_t n = ring.size();
  auto lo = [&](std::size_t i) { return std::min(ring[i].x, Next(ring, i).x); };
  auto hi = [&](std::size_t i) { return std::max(ring[i].x, Next(ring, i).x); };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return lo(a) != lo(b) ? lo(a) < lo(b) : a < b; });
  std::size_t best_i = n, best_j = n;
  bool best_cross = false;
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t e = order[s];
    for (std::size_t t = s + 1; t < n && lo(order[t]) <= hi(e); ++t) {
      const std::size_t i = std::min(e, order[t]), j = std::max(e, order[t]);
      if (j == i + 1 || (i == 0 && j == n - 1))
        continue;  // neighbours share a vertex; FoldedEdge judged them
      const Point2 &a = ring[i], &b = Next(ring, i), &c = ring[j], &d = Next(ring, j);
      if (!planar::SegmentsMeet(a, b, c, d) ||
          std::make_pair(i, j) > std::make_pair(best_i, best_j))
        continue;
      best_i = i;
      best_j = j;
      best_cross = planar::Orient(a, b, c) * planar::Orient(a, b, d) < 0 &&
                   planar::Orient(c, d, a) * planar::Orient(c, d, b) < 0;
    }
  }
  return best_i < n ? Pair("edges", best_i, best_j, best_cross ? "cross" : "touch") : "";
}

// The points that tell how ring `ring` lies against `other`'s boundary (planar.h).
std::vector<Point2> Samples(const Ring& ring, const Footprint& other) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < ring.size(); ++i)
    planar::AppendPieceMidpoints(ring[i], Next(ring, i), other, out);
  return out;
}

}  // namespace

std::string RingDefect(const Ring& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y))
      return "vertex " + std::to_string(i) + " is not a finite point";
  }
  std::size_t distinct = 0;
  const std::string repeated = RepeatedVertex(ring, distinct);
  if (distinct < 3)
    return "fewer than 3 distinct points";
  if (!repeated.empty())
    return repeated;
  for (const std::string& defect : {FoldedEdge(ring), MeetingEdges(ring)}) {
    if (!defect.empty())
      return defect;
  }
  if (SignedArea(ring) == 0)
    return "zero area";
  return "";
}

std::string HoleDefect(const Footprint& footprint, std::size_t hole) {
  const Ring& ring = footprint.holes.at(hole);
  if (std::string defect = RingDefect(ring); !defect.empty())
    return defect;
  const Footprint outer{footprint.outer, {}};
  for (const Point2& p : Samples(ring, outer)) {
    if (planar::RingSide(footprint.outer, p) == planar::Side::kOutside)
      return "reaches outside the outer ring";
  }
  for (std::size_t k = 0; k < hole; ++k) {
    if (InteriorsOverlap(Footprint{ring, {}}, Footprint{footprint.holes[k], {}}, 0.0))
      return "overlaps hole " + std::to_string(k);
  }
  return "";
}

std::string FootprintDefect(const Footprint& footprint) {
  if (std::string defect = RingDefect(footprint.outer); !defect.empty())
    return "outer ring: " + defect;
  for (std::size_t k = 0; k < footprint.holes.size(); ++k) {
    if (std::string defect = HoleDefect(footprint, k); !defect.empty())
      return "hole " + std::to_string(k) + ": " + defect;
  }
  if (!(Area(footprint) > 0))
    return "its holes leave no area";
  return "";
}

bool InteriorsOverlap(const Footprint& a, const Footprint& b, double tolerance) {
  const Bounds2 ba = BoundsOf(a.outer), bb = BoundsOf(b.outer);
  if (std::min(ba.xmax, bb.xmax) - std::max(ba.xmin, bb.xmin) <= tolerance ||
      std::min(ba.ymax, bb.ymax) - std::max(ba.ymin, bb.ymin) <= tolerance)
    return false;
  // Where the interiors overlap, the boundary of the shared part is made of pieces of either
  // boundary lying inside the other footprint, unless both have the same boundary.
  auto samples = [](const Footprint& f, const Footprint& other) {
    std::vector<Point2> out = Samples(f.outer, other);
    for (const auto& hole : f.holes) {
      const std::vector<Point2> more = Samples(hole, other);
      out.insert(out.end(), more.begin(), more.end());
    }
    return out;
  };
  const std::vector<Point2> of_a = samples(a, b), of_b = samples(b, a);
  auto deep_inside = [&](const std::vector<Point2>& points, const Footprint& f) {
    return std::any_of(points.begin(), points.end(), [&](const Point2& p) {
      return planar::FootprintSide(f, p) == planar::Side::kInside &&
             planar::BoundaryDistance(f, p) > tolerance;
    });
  };
  if (deep_inside(of_a, b) || deep_inside(of_b, a))
    return true;
  // The same region twice: every sample on the other's boundary, to rounding.
  const double scale =
      1.0 + std::max({std::abs(ba.xmin), std::abs(ba.xmax), std::abs(ba.ymin), std::abs(ba.ymax)});
  const double rounding = 1e-9 * scale;
  auto on_boundary = [&](const std::vector<Point2>& points, const Footprint& f) {
    return std::all_of(points.begin(), points.end(),
                       [&](const Point2& p) { return planar::BoundaryDistance(f, p) <= rounding; });
  };
  return on_boundary(of_a, b) && on_boundary(of_b, a);
}

}  // namespace rlpos
