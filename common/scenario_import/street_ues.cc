#include "common/scenario_import/street_ues.h"

#include <algorithm>
#include <cmath>

#include "common/scenario_generator/ue_placement.h"

namespace rlpos {
namespace {

constexpr int kTriesPerSpot = 200;

double ToHalfMetre(double v) {
  return std::floor(v * 2.0 + 0.5) / 2.0;
}

// Liang-Barsky: the part of a -> b inside the rectangle, if any.
std::optional<StreetSegment> ClipSegment(const Point2& a, const Point2& b,
                                         const VenueFrame& venue) {
  double t0 = 0, t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x, venue.width - a.x, a.y, venue.depth - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0)
        return std::nullopt;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  if (t0 >= t1)
    return std::nullopt;
  return StreetSegment{{a.x + t0 * dx, a.y + t0 * dy}, {a.x + t1 * dx, a.y + t1 * dy}};
}

double WallDistance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 == 0 ? 0 : std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0., 1.);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool NearWall(const Ring& ring, const Point2& p) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (WallDistance(p, ring[i], ring[(i + 1) % ring.size()]) < kUeClearance)
      return true;
  }
  return false;
}

class SpotDrawer {
 public:
  SpotDrawer(const UeGround& ground, PortableRandom& random) : ground_(ground), random_(random) {
    long long total = 0;
    for (const auto& s : ground.streets) {
      // Lengths in whole centimetres: integer weights draw the same everywhere.
      total += std::max(1LL, std::llround(std::hypot(s.b.x - s.a.x, s.b.y - s.a.y) * 100));
      ends_.push_back(total);
    }
  }

  bool on_streets() const { return !ends_.empty(); }

  // A free spot on a street (or, without streets, anywhere in the venue).
  std::optional<Point2> Anywhere(const std::vector<Vec3>& taken) {
    for (int tries = 0; tries < kTriesPerSpot; ++tries) {
      const Point2 p = on_streets() ? StreetPoint()
                                    : Point2{random_.UniformHalfMetres(0, ground_.venue.width),
                                             random_.UniformHalfMetres(0, ground_.venue.depth)};
      if (Free(p, taken))
        return p;
    }
    return std::nullopt;
  }

  // A free spot in the square of half side `radius` around `centre`.
  std::optional<Point2> Near(const Point2& centre, double radius, const std::vector<Vec3>& taken) {
    for (int tries = 0; tries < kTriesPerSpot; ++tries) {
      const Point2 p{centre.x + random_.UniformHalfMetres(-radius, radius),
                     centre.y + random_.UniformHalfMetres(-radius, radius)};
      if (Free(p, taken))
        return p;
    }
    return std::nullopt;
  }

 private:
  Point2 StreetPoint() {
    const long long u = random_.UniformInt(0, ends_.back() - 1);
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(ends_.begin(), ends_.end(), u) - ends_.begin());
    const long long start = k == 0 ? 0 : ends_[k - 1];
    const double t = (static_cast<double>(u - start) + 0.5) / static_cast<double>(ends_[k] - start);
    const StreetSegment& s = ground_.streets[k];
    return {ToHalfMetre(s.a.x + t * (s.b.x - s.a.x)), ToHalfMetre(s.a.y + t * (s.b.y - s.a.y))};
  }

  bool Free(const Point2& p, const std::vector<Vec3>& taken) const {
    if (!Outdoors(ground_, p))
      return false;
    return std::none_of(taken.begin(), taken.end(),
                        [&](const Vec3& q) { return q.x == p.x && q.y == p.y; });
  }

  const UeGround& ground_;
  PortableRandom& random_;
  std::vector<long long> ends_;  // cumulative street lengths (cm)
};

std::string Count(int n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::vector<StreetSegment> StreetSegments(const std::vector<std::vector<LonLat>>& streets,
                                          const LocalProjection& projection,
                                          const VenueFrame& venue) {
  std::vector<StreetSegment> out;
  for (const auto& line : streets) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Point2 a = ToVenue(line[i], projection, venue);
      const Point2 b = ToVenue(line[i + 1], projection, venue);
      if (a.x == b.x && a.y == b.y)
        continue;
      if (auto piece = ClipSegment(a, b, venue))
        out.push_back(*piece);
    }
  }
  return out;
}

bool Outdoors(const UeGround& ground, const Point2& p) {
  if (p.x < kUeClearance || p.y < kUeClearance || p.x > ground.venue.width - kUeClearance ||
      p.y > ground.venue.depth - kUeClearance) {
    return false;
  }
  for (const auto& f : ground.footprints) {
    const Bounds2 box = BoundsOf(f.outer);
    if (p.x < box.xmin - kUeClearance || p.x > box.xmax + kUeClearance ||
        p.y < box.ymin - kUeClearance || p.y > box.ymax + kUeClearance) {
      continue;
    }
    // Off the footprint, and a clearance from its walls (a courtyard's too).
    if (Contains(f, p) || NearWall(f.outer, p))
      return false;
    for (const auto& hole : f.holes) {
      if (NearWall(hole, p))
        return false;
    }
  }
  return true;
}

std::optional<UeSpots> DrawUeSpots(const UeGround& ground, int count, int groups,
                                   PortableRandom& random) {
  SpotDrawer drawer(ground, random);
  UeSpots spots;
  std::vector<Point2> centres;
  std::vector<double> radii;
  for (int k = 0; k < groups; ++k) {
    const auto centre = drawer.Anywhere({});
    if (!centre)
      return std::nullopt;
    centres.push_back(*centre);
    radii.push_back(static_cast<double>(random.UniformInt(8, 15)));
  }
  for (int i = 0; i < count; ++i) {
    const std::size_t k = groups > 0 ? static_cast<std::size_t>(i % groups) : 0;
    const auto spot = groups > 0 ? drawer.Near(centres[k], radii[k], spots.positions)
                                 : drawer.Anywhere(spots.positions);
    if (!spot)
      return std::nullopt;
    spots.positions.push_back({spot->x, spot->y, kUeHeight});
  }
  spots.summary =
      Count(count, "UE", "UEs") +
      (drawer.on_streets() ? " along the streets" : " outdoors (no streets in the venue)");
  if (groups > 0)
    spots.summary += " in " + Count(groups, "group", "groups");
  return spots;
}

}  // namespace rlpos
