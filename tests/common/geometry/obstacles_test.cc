// Obstacles: ns-3's line-of-sight rule over boxes and prisms, and its grid giving exactly the
// answers of a scan over every solid.
#include "common/geometry/obstacles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

using test_shapes::Courtyard;

TEST(Obstacles, TheRuleOverBoxes) {
  const Obstacles o({Solid::OfBox({0, 10, 0, 10, 0, 20}), Solid::OfBox({20, 30, 0, 10, 0, 5})});
  EXPECT_EQ(o.SolidAt({5, 5, 5}), 0);
  EXPECT_EQ(o.SolidAt({10, 10, 20}), 0);  // a corner counts as inside
  EXPECT_EQ(o.SolidAt({25, 5, 6}), -1);   // above the low one
  EXPECT_EQ(o.FootprintAt(25, 5), 1);
  EXPECT_EQ(o.FootprintAt(15, 5), -1);
  // Outdoors: over the low box, through it, grazing its roof.
  EXPECT_TRUE(o.Los({15, 5, 6}, {35, 5, 6}));
  EXPECT_FALSE(o.Los({15, 5, 4}, {35, 5, 4}));
  EXPECT_FALSE(o.Los({15, 5, 5}, {35, 5, 5}));
  EXPECT_TRUE(o.Blocked({15, 5, 5}, {35, 5, 5}));
  // Past a corner, the bounding boxes overlapping: only the axis across the segment separates.
  EXPECT_TRUE(o.Los({16, 5, 1}, {5, 16, 1}));
  EXPECT_FALSE(o.Los({15, 5, 1}, {5, 15, 1}));  // through the corner (10, 10)
  // Indoors: the same solid sees itself; another solid, or outdoors, does not.
  EXPECT_TRUE(o.Los({1, 1, 1}, {9, 9, 19}));
  EXPECT_FALSE(o.Los({1, 1, 1}, {25, 5, 1}));
  EXPECT_FALSE(o.Los({1, 1, 1}, {15, 5, 30}));
  EXPECT_FALSE(o.Los({15, 5, 30}, {1, 1, 1}));
}

TEST(Obstacles, TheRuleOverPrisms) {
  // A courtyard building [0, 20]^2 less [5, 15]^2, 10 m; a bridge part above a passage,
  // [30, 40] x [0, 20] from 4 m to 8 m.
  const Obstacles o({Solid::Prism(Courtyard(), 0, 10),
                     Solid::Prism({test_shapes::Rect(30, 0, 40, 20), {}}, 4, 8)});
  EXPECT_EQ(o.SolidAt({10, 10, 1.5}), -1);  // in the courtyard
  EXPECT_EQ(o.SolidAt({2, 10, 1.5}), 0);
  EXPECT_EQ(o.FootprintAt(10, 10), -1);
  EXPECT_EQ(o.SolidAt({35, 10, 1.5}), -1);  // under the bridge
  EXPECT_EQ(o.SolidAt({35, 10, 4}), 1);
  EXPECT_EQ(o.FootprintAt(35, 10), 1);  // its ground shape, whatever its heights
  // Within the courtyard; from it over the wall; from it through the wall.
  EXPECT_TRUE(o.Los({6, 6, 1.5}, {14, 14, 1.5}));
  EXPECT_TRUE(o.Los({10, 10, 1.5}, {10, 10, 50}));
  EXPECT_TRUE(o.Los({10, 10, 11}, {-10, 10, 11}));
  EXPECT_FALSE(o.Los({10, 10, 1.5}, {-10, 10, 1.5}));
  // Under the bridge, over it, through it.
  EXPECT_TRUE(o.Los({35, -5, 2}, {35, 25, 2}));
  EXPECT_TRUE(o.Los({35, -5, 9}, {35, 25, 9}));
  EXPECT_FALSE(o.Los({35, -5, 6}, {35, 25, 6}));
  EXPECT_FALSE(o.Los({35, -5, 4}, {35, 25, 4}));  // along its underside
  EXPECT_FALSE(o.Los({35, -4, 8}, {35, 4, 0}));   // across its underside's edge only
  EXPECT_TRUE(o.Los({35, -4, 7.9}, {35, 4, -0.1}));
}

TEST(Obstacles, NoneBlockNothing) {
  const Obstacles none;
  EXPECT_EQ(none.SolidAt({0, 0, 0}), -1);
  EXPECT_EQ(none.FootprintAt(0, 0), -1);
  EXPECT_FALSE(none.Blocked({0, 0, 0}, {10, 10, 10}));
  EXPECT_TRUE(none.Los({0, 0, 0}, {10, 10, 10}));
}

// A random city: boxes and prisms (some with a courtyard, some starting above the ground).
std::vector<Solid> RandomSolids(std::mt19937_64& rng, int count, double extent) {
  std::uniform_real_distribution<double> at(0, extent), size(2, 40), height(3, 50), unit(0, 1);
  std::vector<Solid> solids;
  for (int i = 0; i < count; ++i) {
    const double x = at(rng), y = at(rng), h = height(rng);
    if (i % 2 == 0) {
      solids.push_back(Solid::OfBox({x, x + size(rng), y, y + size(rng), 0, h}));
      continue;
    }
    const double r = size(rng);
    Footprint f{test_shapes::RandomStar(rng, x, y, 0.4 * r, r, 5 + i % 9), {}};
    if (i % 5 == 1)
      f.holes.push_back(test_shapes::RandomStar(rng, x, y, 0.05 * r, 0.3 * r, 4));
    const double zmin = i % 7 == 3 ? 0.5 * h * unit(rng) : 0.0;
    solids.push_back(Solid::Prism(std::move(f), zmin, h));
  }
  return solids;
}

// Segments that find the edge cases: random ones, vertical and level ones, ones aimed at a box's
// corner or ending on a box's face.
std::vector<std::pair<Vec3, Vec3>> Segments(std::mt19937_64& rng, const std::vector<Solid>& solids,
                                            int count, double extent) {
  std::uniform_real_distribution<double> at(-0.05 * extent, 1.05 * extent), z(0, 60);
  std::uniform_int_distribution<std::size_t> pick(0, solids.size() - 1);
  std::vector<std::pair<Vec3, Vec3>> out;
  for (int i = 0; i < count; ++i) {
    Vec3 a{at(rng), at(rng), z(rng)}, b{at(rng), at(rng), z(rng)};
    const Box& box = solids[pick(rng)].box;
    switch (i % 6) {
      case 1:
        b = {a.x, a.y, z(rng)};  // vertical
        break;
      case 2:
        b.z = a.z;  // level
        break;
      case 3:  // through a corner of a box's top
        b = {2 * box.xmax - a.x, 2 * box.ymin - a.y, 2 * box.zmax - a.z};
        break;
      case 4:  // ending on a face
        b = {box.xmin, 0.5 * (box.ymin + box.ymax), 0.5 * (box.zmin + box.zmax)};
        break;
      case 5:  // short
        b = {a.x + 0.01 * (b.x - a.x), a.y + 0.01 * (b.y - a.y), b.z};
        break;
      default:
        break;
    }
    out.push_back({a, b});
  }
  return out;
}

int LinearSolidAt(const Obstacles& o, const Vec3& p) {
  for (std::size_t i = 0; i < o.size(); ++i) {
    if (o.Holds(i, p))
      return static_cast<int>(i);
  }
  return -1;
}

TEST(Obstacles, GridAnswersAsAScanOfEverySolid) {
  for (const int count : {1, 7, 400}) {
    std::mt19937_64 rng(1000 + count);
    const double extent = 1000;
    const std::vector<Solid> solids = RandomSolids(rng, count, extent);
    const auto segments = Segments(rng, solids, 6000, extent);
    const Obstacles o(solids);
    int blocked = 0, indoors = 0;
    for (const auto& [a, b] : segments) {
      bool want_blocked = false;
      for (std::size_t i = 0; i < o.size() && !want_blocked; ++i)
        want_blocked = o.Meets(i, a, b);
      ASSERT_EQ(o.Blocked(a, b), want_blocked)
          << count << " solids, (" << a.x << ", " << a.y << ", " << a.z << ") - (" << b.x << ", "
          << b.y << ", " << b.z << ")";
      const int in_a = LinearSolidAt(o, a), in_b = LinearSolidAt(o, b);
      ASSERT_EQ(o.SolidAt(a), in_a);
      ASSERT_EQ(o.SolidAt(b), in_b);
      const bool want_los = (in_a >= 0 || in_b >= 0) ? in_a == in_b : !want_blocked;
      ASSERT_EQ(o.Los(a, b), want_los);
      int ground = -1;
      for (std::size_t i = 0; i < o.size() && ground < 0; ++i)
        ground = o.HoldsGround(i, b.x, b.y) ? static_cast<int>(i) : -1;
      ASSERT_EQ(o.FootprintAt(b.x, b.y), ground);
      blocked += want_blocked ? 1 : 0;
      indoors += in_b >= 0 ? 1 : 0;
    }
    if (count == 400) {  // the draw reaches every case
      EXPECT_GT(blocked, 1000);
      EXPECT_LT(blocked, 5000);
      EXPECT_GT(indoors, 200);
    }
  }
}

// A prism's test against its own footprint's: the solid adds only the bounding-box shortcut.
TEST(Obstacles, PrismMeetsAsItsFootprint) {
  std::mt19937_64 rng(7);
  const std::vector<Solid> solids = RandomSolids(rng, 40, 200);
  const Obstacles o(solids);
  for (const auto& [a, b] : Segments(rng, solids, 4000, 200)) {
    for (std::size_t i = 0; i < o.size(); ++i) {
      const Solid& s = o.solid(i);
      if (s.IsBox())
        continue;
      ASSERT_EQ(o.Meets(i, a, b), SegmentMeetsPrism(s.footprint, s.box.zmin, s.box.zmax, a, b));
    }
  }
}

// The grid keeps a short query to the solids near it among many.
TEST(Obstacles, GridLooksNearby) {
  std::vector<Bounds2> bounds;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j)
      bounds.push_back({20.0 * i, 20.0 * j, 20.0 * i + 10, 20.0 * j + 10});
  }
  const SolidGrid grid(bounds);
  std::vector<int> near;
  grid.Along({505, 505}, {545, 525}, near);
  EXPECT_GE(near.size(), 4u);
  EXPECT_LE(near.size(), 20u);
  std::sort(near.begin(), near.end());
  EXPECT_TRUE(std::adjacent_find(near.begin(), near.end()) == near.end());  // each once
  const auto [begin, end] = grid.At(505, 505);
  EXPECT_LE(end - begin, 4);
}

}  // namespace
}  // namespace rlpos
