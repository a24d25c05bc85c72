// The shortcuts of the line-of-sight queries give the answers of the plain tests: the grid walk
// (no sort, a per-thread stamp) against a scan of every solid, the height slice's bounding box
// and the edges-first segment test against the plain prism test, the box-first point-on-segment
// test against the orientation-first one. Random footprints with several holes, parts above the
// ground, far-off coordinates, and segments from the street to the sky that end on heights,
// vertices and edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <thread>

#include "common/geometry/obstacles.h"
#include "common/geometry/planar.h"
#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

// The tests as they were before the shortcuts, kept here as the reference.
bool PlainOnSegment(const Point2& p, const Point2& a, const Point2& b) {
  return planar::Orient(a, b, p) == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) &&
         p.y >= std::min(a.y, b.y) && p.y <= std::max(a.y, b.y);
}

bool PlainSegmentMeets(const Footprint& f, const Point2& a, const Point2& b) {
  if (Contains(f, a))
    return true;
  auto meets_ring = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (planar::SegmentsMeet(a, b, ring[i], planar::Next(ring, i)))
        return true;
    }
    return false;
  };
  return meets_ring(f.outer) || std::any_of(f.holes.begin(), f.holes.end(), meets_ring);
}

bool PlainMeetsPrism(const Footprint& f, double zmin, double zmax, const Vec3& a, const Vec3& b) {
  const Point2 a2{a.x, a.y}, b2{b.x, b.y};
  if (a.x == b.x && a.y == b.y)
    return std::max(a.z, b.z) >= zmin && std::min(a.z, b.z) <= zmax && Contains(f, a2);
  if (a.z == b.z)
    return a.z >= zmin && a.z <= zmax && PlainSegmentMeets(f, a2, b2);
  // The cut to the heights is the library's (no shortcut in it); the plane test is the plain one.
  Point2 from, to;
  return HeightSlice(a, b, zmin, zmax, from, to) && PlainSegmentMeets(f, from, to);
}

// A star-shaped outer ring (8-14 vertices, radii in [0.6 r, r]) with 0-3 small holes on a circle
// of 0.3 r: they lie inside it and apart from each other.
Footprint HoledFootprint(std::mt19937_64& rng, double cx, double cy, double r, int holes) {
  std::uniform_int_distribution<int> vertices(8, 14);
  Footprint f{test_shapes::RandomStar(rng, cx, cy, 0.6 * r, r, vertices(rng)), {}};
  for (int k = 0; k < holes; ++k) {
    const double angle = 2 * M_PI * k / 3;
    f.holes.push_back(test_shapes::RandomStar(rng, cx + 0.3 * r * std::cos(angle),
                                              cy + 0.3 * r * std::sin(angle), 0.04 * r, 0.1 * r,
                                              4 + k));
  }
  return f;
}

// A district: prisms with holes, some starting above the ground (a part on a roof, a bridge),
// and boxes; around (x0, y0), which may be far from the origin.
std::vector<Solid> District(std::mt19937_64& rng, int count, double x0, double y0, double extent) {
  std::uniform_real_distribution<double> at(0, extent), size(4, 30), height(3, 60), unit(0, 1);
  std::vector<Solid> solids;
  for (int i = 0; i < count; ++i) {
    const double x = x0 + at(rng), y = y0 + at(rng), h = height(rng);
    if (i % 5 == 4) {
      solids.push_back(Solid::OfBox({x, x + size(rng), y, y + size(rng), 0, h}));
      continue;
    }
    Footprint f = HoledFootprint(rng, x, y, size(rng), i % 4);
    EXPECT_EQ(FootprintDefect(f), "");
    const double zmin = i % 3 == 1 ? 0.6 * h * unit(rng) : 0.0;
    solids.push_back(Solid::Prism(std::move(f), zmin, h));
  }
  return solids;
}

// Segments as the env asks them (a UE at 1.5 m to a UAV in the air) and ones that end where
// rounding decides: on a prism's floor or roof height, on a vertex, on an edge's middle; level at
// a prism's floor; vertical through a footprint.
std::vector<std::pair<Vec3, Vec3>> Queries(std::mt19937_64& rng, const std::vector<Solid>& solids,
                                           int count, double x0, double y0, double extent) {
  std::uniform_real_distribution<double> at(-0.05 * extent, 1.05 * extent), z(5, 80);
  std::uniform_int_distribution<std::size_t> pick(0, solids.size() - 1);
  std::vector<std::pair<Vec3, Vec3>> out;
  for (int i = 0; i < count; ++i) {
    Vec3 a{x0 + at(rng), y0 + at(rng), 1.5}, b{x0 + at(rng), y0 + at(rng), z(rng)};
    const Solid& s = solids[pick(rng)];
    const Ring& ring = s.IsBox() ? test_shapes::Rect(s.box.xmin, s.box.ymin, s.box.xmax, s.box.ymax)
                                 : s.footprint.outer;
    const Point2& v = ring[static_cast<std::size_t>(i) % ring.size()];
    const Point2& w = planar::Next(ring, static_cast<std::size_t>(i) % ring.size());
    switch (i % 7) {
      case 1:
        b.z = s.box.zmax;  // ends at the roof's height
        break;
      case 2:
        a.z = s.box.zmin;  // starts at the floor's height
        break;
      case 3:
        b = {v.x, v.y, 0.5 * (s.box.zmin + s.box.zmax)};  // onto a vertex
        break;
      case 4:
        b = {0.5 * (v.x + w.x), 0.5 * (v.y + w.y), z(rng)};  // onto an edge
        break;
      case 5:
        a.z = b.z = s.box.zmin;  // level with a floor
        break;
      case 6:
        b = {a.x, a.y, z(rng)};  // vertical
        break;
      default:
        break;
    }
    out.push_back({a, b});
  }
  return out;
}

int ScanSolidAt(const Obstacles& o, const Vec3& p) {
  for (std::size_t i = 0; i < o.size(); ++i) {
    if (o.Holds(i, p))
      return static_cast<int>(i);
  }
  return -1;
}

bool ScanBlocked(const Obstacles& o, const Vec3& a, const Vec3& b) {
  for (std::size_t i = 0; i < o.size(); ++i) {
    const Solid& s = o.solid(i);
    if (s.IsBox() ? o.Meets(i, a, b) : PlainMeetsPrism(s.footprint, s.box.zmin, s.box.zmax, a, b))
      return true;
  }
  return false;
}

// Every query of `o` against the scan; the count of blocked ones.
int ExpectAsAScan(const Obstacles& o, const std::vector<std::pair<Vec3, Vec3>>& queries) {
  int blocked = 0;
  for (const auto& [a, b] : queries) {
    const bool want = ScanBlocked(o, a, b);
    EXPECT_EQ(o.Blocked(a, b), want) << "(" << a.x << ", " << a.y << ", " << a.z << ") - (" << b.x
                                     << ", " << b.y << ", " << b.z << ")";
    const int in_a = ScanSolidAt(o, a), in_b = ScanSolidAt(o, b);
    EXPECT_EQ(o.SolidAt(a), in_a);
    EXPECT_EQ(o.SolidAt(b), in_b);
    EXPECT_EQ(o.Los(a, b), (in_a >= 0 || in_b >= 0) ? in_a == in_b : !want);
    blocked += want ? 1 : 0;
  }
  return blocked;
}

TEST(FastPaths, PrismMeetsAsThePlainTest) {
  std::mt19937_64 rng(11);
  for (const double x0 : {0.0, 385000.0}) {  // local metres, and a UTM-like easting
    const double y0 = x0 == 0 ? 0.0 : 6672000.0;
    const std::vector<Solid> solids = District(rng, 60, x0, y0, 300);
    const Obstacles o(solids);
    int met = 0;
    for (const auto& [a, b] : Queries(rng, solids, 3000, x0, y0, 300)) {
      for (std::size_t i = 0; i < o.size(); ++i) {
        const Solid& s = o.solid(i);
        if (s.IsBox())
          continue;
        const bool want = PlainMeetsPrism(s.footprint, s.box.zmin, s.box.zmax, a, b);
        ASSERT_EQ(o.Meets(i, a, b), want) << "solid " << i;
        ASSERT_EQ(SegmentMeetsPrism(s.footprint, s.box.zmin, s.box.zmax, a, b), want);
        met += want ? 1 : 0;
      }
    }
    EXPECT_GT(met, 2000);  // the draw meets prisms often, not only misses them
  }
}

TEST(FastPaths, GridAnswersAsAScanOverADistrict) {
  for (const int count : {1, 5, 400}) {
    std::mt19937_64 rng(2000 + count);
    const std::vector<Solid> solids = District(rng, count, 0, 0, 1000);
    const Obstacles o(solids);
    const int blocked = ExpectAsAScan(o, Queries(rng, solids, 6000, 0, 0, 1000));
    if (count == 400) {
      EXPECT_GT(blocked, 1000);
      EXPECT_LT(blocked, 5500);
    }
  }
}

TEST(FastPaths, PointOnSegmentAsOrientationFirst) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> grid(-4, 4);
  std::uniform_real_distribution<double> any(-4, 4);
  int on = 0;
  for (int i = 0; i < 200000; ++i) {
    // Whole and half coordinates land exactly on segments and their ends; others near them.
    const Point2 a{1.0 * grid(rng), 1.0 * grid(rng)}, b{1.0 * grid(rng), 1.0 * grid(rng)};
    Point2 p{0.5 * grid(rng), 0.5 * grid(rng)};
    if (i % 3 == 0)
      p = {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    if (i % 3 == 1)
      p = {any(rng), any(rng)};
    const bool want = PlainOnSegment(p, a, b);
    ASSERT_EQ(planar::OnSegment(p, a, b), want);
    on += want ? 1 : 0;
  }
  EXPECT_GT(on, 60000);
}

// The grid lists each solid once whatever the cells it spans, every solid a segment meets among
// them, and stops where asked.
TEST(FastPaths, WalkListsEachSolidOnce) {
  std::mt19937_64 rng(3);
  const std::vector<Solid> solids = District(rng, 300, 0, 0, 500);
  std::vector<Bounds2> bounds;
  for (const auto& s : solids)
    bounds.push_back({s.box.xmin, s.box.ymin, s.box.xmax, s.box.ymax});
  const SolidGrid grid(bounds);
  const Obstacles o(solids);
  std::vector<int> listed;
  std::size_t most = 0;
  for (const auto& [a, b] : Queries(rng, solids, 2000, 0, 0, 500)) {
    grid.Along({a.x, a.y}, {b.x, b.y}, listed);
    const std::set<int> once(listed.begin(), listed.end());
    ASSERT_EQ(once.size(), listed.size());
    most = std::max(most, listed.size());
    for (std::size_t i = 0; i < o.size(); ++i) {
      if (o.Meets(i, a, b)) {
        ASSERT_EQ(once.count(static_cast<int>(i)), 1u) << "solid " << i << " left out";
      }
    }
    if (listed.size() >= 3) {
      int calls = 0;
      EXPECT_TRUE(grid.AnyAlong({a.x, a.y}, {b.x, b.y}, [&](int) { return ++calls == 3; }));
      EXPECT_EQ(calls, 3);
    }
  }
  EXPECT_GT(most, 20u);  // long segments span many cells
}

// Queries of two obstacle sets interleaved on one thread, and on several threads at once: each
// thread's stamps keep their lists apart.
TEST(FastPaths, InterleavedAndConcurrentQueries) {
  std::mt19937_64 rng(9);
  const std::vector<Solid> small = District(rng, 7, 0, 0, 100);
  const std::vector<Solid> large = District(rng, 400, 0, 0, 1000);
  const Obstacles os(small), ol(large);
  const auto qs = Queries(rng, small, 2000, 0, 0, 100);
  const auto ql = Queries(rng, large, 2000, 0, 0, 1000);
  std::vector<char> want_s, want_l;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    want_s.push_back(ScanBlocked(os, qs[k].first, qs[k].second));
    want_l.push_back(ScanBlocked(ol, ql[k].first, ql[k].second));
  }
  auto run = [&](int& wrong) {
    for (int round = 0; round < 3; ++round) {
      for (std::size_t k = 0; k < qs.size(); ++k) {
        wrong += os.Blocked(qs[k].first, qs[k].second) != static_cast<bool>(want_s[k]);
        wrong += ol.Blocked(ql[k].first, ql[k].second) != static_cast<bool>(want_l[k]);
      }
    }
  };
  int wrong_here = 0, wrong_there = 0;
  std::thread other(run, std::ref(wrong_there));
  run(wrong_here);
  other.join();
  EXPECT_EQ(wrong_here, 0);
  EXPECT_EQ(wrong_there, 0);
}

}  // namespace
}  // namespace rlpos
