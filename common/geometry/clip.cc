// ClipToRectangle: a footprint cut by the venue's edge. Each side of the rectangle cuts each ring
// in turn (a half-plane cut); a concave ring may fall into several pieces.
#include <algorithm>
#include <cmath>

#include "common/geometry/footprint.h"
#include "common/geometry/planar.h"

namespace rlpos {
namespace {

using planar::Next;

// A side of the rectangle: keeps the points where D >= 0.
struct HalfPlane {
  bool vertical;  // the line is x = value (else y = value)
  double value;
  double sign;  // +1 keeps the side above value, -1 the side below
  double D(const Point2& p) const { return sign * ((vertical ? p.x : p.y) - value); }
  // The coordinate along the line.
  double U(const Point2& p) const { return vertical ? p.y : p.x; }
  Point2 At(double u) const { return vertical ? Point2{value, u} : Point2{u, value}; }
};

// Where a ring's edge crosses the line. Only points strictly on the kept side count as kept: the
// cut is taken as the limit of a cut by a line moved a hair into the kept side (simulation of
// simplicity), so that a wall lying on the line with the building behind it leaves no bridge of
// zero width between pieces. Ties along the line are broken by how each crossing would slide
// as the line moves (du).
struct Crossing {
  std::size_t edge;  // the edge it lies on
  bool entry;        // the ring passes from the dropped side to the kept one
  Point2 point;
  double u, du;
};

// Drops repeated points and zero-width spikes the cut may leave along the line.
Ring Clean(Ring ring) {
  bool changed = true;
  while (changed && ring.size() >= 3) {
    changed = false;
    for (std::size_t k = 0; k < ring.size() && ring.size() >= 3; ++k) {
      const Point2& prev = ring[(k + ring.size() - 1) % ring.size()];
      const Point2& at = ring[k];
      const Point2& next = Next(ring, k);
      const double dot = (prev.x - at.x) * (next.x - at.x) + (prev.y - at.y) * (next.y - at.y);
      if (planar::SamePoint(prev, at) || (planar::Orient(prev, at, next) == 0 && dot >= 0)) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
        break;
      }
    }
  }
  if (ring.size() < 3 || SignedArea(ring) == 0)
    return {};
  return ring;
}

// Sutherland-Hodgman: one ring, which may run along the line between pieces. Only for input
// whose crossings do not pair up (a ring that is not simple, to rounding).
std::vector<Ring> CutAsOne(const Ring& ring, const HalfPlane& h) {
  Ring out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& p = ring[i];
    const Point2& q = Next(ring, i);
    const double dp = h.D(p), dq = h.D(q);
    if (dp >= 0)
      out.push_back(p);
    if ((dp >= 0) != (dq >= 0))
      out.push_back(h.At(h.U(p) + dp / (dp - dq) * (h.U(q) - h.U(p))));
  }
  Ring clean = Clean(out);
  return clean.empty() ? std::vector<Ring>{} : std::vector<Ring>{clean};
}

std::vector<Crossing> Crossings(const Ring& ring, const HalfPlane& h) {
  std::vector<Crossing> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& p = ring[i];
    const Point2& q = Next(ring, i);
    const bool p_kept = h.D(p) > 0, q_kept = h.D(q) > 0;
    if (p_kept == q_kept)
      continue;
    const Point2& k = p_kept ? p : q;
    const Point2& m = p_kept ? q : p;
    const double dk = h.D(k), dm = h.D(m);  // dk > 0 >= dm
    Crossing c{i, !p_kept, m, h.U(m), (h.U(k) - h.U(m)) / (dk - dm)};
    if (dm < 0) {
      c.u = h.U(k) + dk / (dk - dm) * (h.U(m) - h.U(k));
      c.point = h.At(c.u);
    }
    out.push_back(c);
  }
  return out;
}

// The kept part of a simple ring: the runs of kept vertices between an entry and the next exit,
// each exit joined along the line to the entry at the other end of the stretch of line inside the
// ring (the crossings sorted along the line pair up: 0-1, 2-3, ...).
std::vector<Ring> Cut(const Ring& ring, const HalfPlane& h) {
  bool any_beyond = false, any_kept = false;
  for (const auto& p : ring) {
    any_beyond = any_beyond || h.D(p) < 0;
    any_kept = any_kept || h.D(p) > 0;
  }
  if (!any_beyond)
    return {ring};
  if (!any_kept)
    return {};
  const std::vector<Crossing> cs = Crossings(ring, h);
  const std::size_t m = cs.size();
  std::vector<std::size_t> order(m);
  for (std::size_t k = 0; k < m; ++k)
    order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (cs[a].u != cs[b].u)
      return cs[a].u < cs[b].u;
    return cs[a].du != cs[b].du ? cs[a].du < cs[b].du : a < b;
  });
  std::vector<std::size_t> partner(m);
  for (std::size_t k = 0; k + 1 < m; k += 2) {
    if (cs[order[k]].entry == cs[order[k + 1]].entry)
      return CutAsOne(ring, h);
    partner[order[k]] = order[k + 1];
    partner[order[k + 1]] = order[k];
  }
  std::vector<Ring> pieces;
  std::vector<bool> used(m, false);
  for (std::size_t first = 0; first < m; ++first) {
    if (!cs[first].entry || used[first])
      continue;
    Ring piece;
    for (std::size_t at = first;;) {
      if (used[at])
        return CutAsOne(ring, h);
      used[at] = true;
      const std::size_t exit = (at + 1) % m;  // crossings alternate along the ring
      piece.push_back(cs[at].point);
      for (std::size_t v = (cs[at].edge + 1) % ring.size();; v = (v + 1) % ring.size()) {
        piece.push_back(ring[v]);
        if (v == cs[exit].edge)
          break;
      }
      piece.push_back(cs[exit].point);
      at = partner[exit];
      if (!cs[at].entry)
        return CutAsOne(ring, h);
      if (at == first)
        break;
    }
    if (Ring clean = Clean(piece); !clean.empty())
      pieces.push_back(std::move(clean));
  }
  return pieces;
}

std::vector<Ring> CutToRectangle(const Ring& ring, const Bounds2& r) {
  std::vector<Ring> pieces{ring};
  for (const HalfPlane& h : {HalfPlane{true, r.xmin, 1.0}, HalfPlane{true, r.xmax, -1.0},
                             HalfPlane{false, r.ymin, 1.0}, HalfPlane{false, r.ymax, -1.0}}) {
    std::vector<Ring> next;
    for (const auto& piece : pieces) {
      for (auto& part : Cut(piece, h))
        next.push_back(std::move(part));
    }
    pieces = std::move(next);
  }
  return pieces;
}

// The piece a cut hole lies in: the one that holds most of its vertices and edges' middles
// strictly inside (pieces do not overlap, so only its own can hold any, rounding aside); failing
// that, one that holds none of them outside (the hole fills the piece).
int PieceOf(const Ring& hole, const std::vector<Footprint>& pieces) {
  int best = -1, fallback = -1;
  std::size_t best_inside = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    std::size_t inside = 0;
    bool outside = false;
    for (std::size_t i = 0; i < hole.size(); ++i) {
      const Point2& a = hole[i];
      const Point2& b = Next(hole, i);
      for (const Point2& p : {a, Point2{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}}) {
        const planar::Side side = planar::RingSide(pieces[k].outer, p);
        inside += side == planar::Side::kInside ? 1 : 0;
        outside = outside || side == planar::Side::kOutside;
      }
    }
    if (inside > best_inside) {
      best = static_cast<int>(k);
      best_inside = inside;
    }
    if (!outside && fallback < 0)
      fallback = static_cast<int>(k);
  }
  return best >= 0 ? best : fallback;
}

}  // namespace

std::vector<Footprint> ClipToRectangle(const Footprint& footprint, const Bounds2& rectangle) {
  std::vector<Footprint> pieces;
  for (auto& ring : CutToRectangle(footprint.outer, rectangle))
    pieces.push_back({std::move(ring), {}});
  for (const auto& hole : footprint.holes) {
    for (auto& part : CutToRectangle(hole, rectangle)) {
      const int k = PieceOf(part, pieces);
      if (k >= 0)
        pieces[static_cast<std::size_t>(k)].holes.push_back(std::move(part));
    }
  }
  // A piece its holes fill entirely has no area left.
  std::vector<Footprint> out;
  for (auto& piece : pieces) {
    if (Area(piece) > 1e-9 * std::abs(SignedArea(piece.outer)))
      out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace rlpos
