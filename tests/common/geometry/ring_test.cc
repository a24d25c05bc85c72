// Rings and footprints: areas, bounds, and why a shape is refused (RingDefect, HoleDefect,
// FootprintDefect).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "common/geometry/footprint.h"
#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

using test_shapes::Courtyard;
using test_shapes::LShape;
using test_shapes::Rect;

TEST(Ring, AreaAndOrientation) {
  EXPECT_DOUBLE_EQ(SignedArea(Rect(0, 0, 4, 3)), 12.0);
  Ring clockwise = Rect(0, 0, 4, 3);
  std::reverse(clockwise.begin(), clockwise.end());
  EXPECT_DOUBLE_EQ(SignedArea(clockwise), -12.0);
  EXPECT_DOUBLE_EQ(SignedArea(LShape()), 10 * 4 + 4 * 6);
  EXPECT_DOUBLE_EQ(Area(Courtyard()), 400.0 - 100.0);
  const Bounds2 b = BoundsOf(LShape());
  EXPECT_EQ(b.xmin, 0);
  EXPECT_EQ(b.ymin, 0);
  EXPECT_EQ(b.xmax, 10);
  EXPECT_EQ(b.ymax, 10);
}

TEST(Ring, SimpleShapesHaveNoDefect) {
  EXPECT_EQ(RingDefect(Rect(0, 0, 1, 1)), "");
  EXPECT_EQ(RingDefect(LShape()), "");
  EXPECT_EQ(RingDefect(test_shapes::UShape()), "");
  EXPECT_EQ(FootprintDefect(Courtyard()), "");
  // Three vertices in a line (a wall split in two) are fine.
  EXPECT_EQ(RingDefect({{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}}), "");
}

TEST(Ring, DefectsInWords) {
  EXPECT_EQ(RingDefect({{0, 0}, {1, 0}}), "fewer than 3 distinct points");
  EXPECT_EQ(RingDefect({{0, 0}, {1, 0}, {0, 0}}), "fewer than 3 distinct points");
  // A bow-tie: edge 0 (0,0)-(10,10) crosses edge 2 (10,0)-(0,10).
  EXPECT_EQ(RingDefect({{0, 0}, {10, 10}, {10, 0}, {0, 10}}), "edges 0 and 2 cross");
  // A repeated vertex, next to itself or further on (the ring pinches).
  EXPECT_EQ(RingDefect({{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}}), "vertices 1 and 2 coincide");
  EXPECT_EQ(RingDefect({{0, 0}, {5, 5}, {10, 0}, {10, 10}, {5, 5}, {0, 10}}),
            "vertices 1 and 4 coincide");
  // A spike: edge 2 runs back along edge 1.
  EXPECT_EQ(RingDefect({{0, 0}, {10, 0}, {10, 10}, {10, 5}, {0, 10}}), "edges 1 and 2 overlap");
  // All in a line: the ring folds back on itself.
  EXPECT_EQ(RingDefect({{0, 0}, {5, 0}, {10, 0}}), "edges 0 and 2 overlap");
  // A vertex on an edge that is not its own: edges 2 and 3 meet edge 0 at (5, 0).
  EXPECT_EQ(RingDefect({{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}}), "edges 0 and 2 touch");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(RingDefect({{0, 0}, {1, 0}, {nan, 1}}), "vertex 2 is not a finite point");
}

TEST(Footprint, HoleDefects) {
  Footprint f = Courtyard();
  f.holes.push_back(Rect(30, 30, 35, 35));
  EXPECT_EQ(HoleDefect(f, 1), "reaches outside the outer ring");
  EXPECT_EQ(FootprintDefect(f), "hole 1: reaches outside the outer ring");
  f.holes[1] = Rect(15, 2, 25, 4);  // through the outer ring
  EXPECT_EQ(HoleDefect(f, 1), "reaches outside the outer ring");
  f.holes[1] = Rect(10, 10, 12, 12);  // inside the first hole
  EXPECT_EQ(HoleDefect(f, 1), "overlaps hole 0");
  f.holes[1] = Rect(14, 14, 17, 17);  // across the first hole's corner
  EXPECT_EQ(HoleDefect(f, 1), "overlaps hole 0");
  f.holes[1] = {{1, 1}, {2, 2}, {1, 2}, {2, 1}};  // a bow-tie
  EXPECT_EQ(FootprintDefect(f), "hole 1: edges 0 and 2 cross");
  // Touching the outer ring (a clipped courtyard) or another hole is fine.
  f.holes[1] = Rect(0, 1, 2, 3);
  EXPECT_EQ(FootprintDefect(f), "");
  f.holes[1] = Rect(15, 5, 18, 8);
  EXPECT_EQ(FootprintDefect(f), "");
  // Holes that fill it leave nothing.
  EXPECT_EQ(FootprintDefect({Rect(0, 0, 1, 1), {Rect(0, 0, 1, 1)}}), "its holes leave no area");
}

}  // namespace
}  // namespace rlpos
