// InteriorsOverlap: shared walls and thin slivers are not overlaps; a shared area is, however
// the two shapes cross.
#include <gtest/gtest.h>

#include "common/geometry/footprint.h"
#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

using test_shapes::Courtyard;
using test_shapes::Rect;
using test_shapes::Square;

constexpr double kMm = 1e-3;

TEST(InteriorsOverlap, TouchingIsNotOverlapping) {
  EXPECT_FALSE(InteriorsOverlap(Square(0, 0, 10), Square(10, 0, 10), kMm));   // a shared wall
  EXPECT_FALSE(InteriorsOverlap(Square(0, 0, 10), Square(10, 10, 10), kMm));  // a corner
  EXPECT_FALSE(InteriorsOverlap(Square(0, 0, 10), Square(10, 3, 4), 0.0));    // part of a wall
  EXPECT_FALSE(InteriorsOverlap(Square(0, 0, 10), Square(20, 0, 10), kMm));
  // A building filling a courtyard exactly.
  EXPECT_FALSE(InteriorsOverlap(Courtyard(), Square(5, 5, 10), kMm));
  EXPECT_FALSE(InteriorsOverlap(Courtyard(), Square(6, 6, 2), kMm));
  // An L and the square in its notch.
  EXPECT_FALSE(InteriorsOverlap({test_shapes::LShape(), {}}, Square(4, 4, 6), kMm));
}

TEST(InteriorsOverlap, ThinOverlapsUnderTheTolerance) {
  EXPECT_FALSE(InteriorsOverlap(Square(0, 0, 10), Square(10 - 0.5 * kMm, 0, 10), kMm));
  EXPECT_TRUE(InteriorsOverlap(Square(0, 0, 10), Square(10 - 0.5 * kMm, 0, 10), 0.0));
  EXPECT_TRUE(InteriorsOverlap(Square(0, 0, 10), Square(10 - 10 * kMm, 0, 10), kMm));
  // Into an L's arm from its notch: the bounds overlap widely, the interiors by a sliver.
  const Footprint l{test_shapes::LShape(), {}};
  EXPECT_FALSE(InteriorsOverlap(l, {Rect(4 - 0.5 * kMm, 4, 10, 10), {}}, kMm));
  EXPECT_TRUE(InteriorsOverlap(l, {Rect(4 - 0.5 * kMm, 4, 10, 10), {}}, 0.0));
  EXPECT_TRUE(InteriorsOverlap(l, {Rect(4 - 10 * kMm, 4, 10, 10), {}}, kMm));
}

TEST(InteriorsOverlap, SharedAreas) {
  EXPECT_TRUE(InteriorsOverlap(Square(0, 0, 10), Square(5, 5, 10), kMm));
  EXPECT_TRUE(InteriorsOverlap(Square(0, 0, 10), Square(0, 0, 10), kMm));  // the same
  EXPECT_TRUE(InteriorsOverlap(Square(0, 0, 10), Square(2, 2, 3), kMm));   // one within
  EXPECT_TRUE(InteriorsOverlap(Square(2, 2, 3), Square(0, 0, 10), kMm));
  // A cross: no vertex of either inside the other.
  EXPECT_TRUE(InteriorsOverlap({Rect(0, 4, 10, 6), {}}, {Rect(4, 0, 6, 10), {}}, kMm));
  // Over a courtyard's wall.
  EXPECT_TRUE(InteriorsOverlap(Courtyard(), Square(3, 8, 4), kMm));
  EXPECT_TRUE(InteriorsOverlap(Courtyard(), Courtyard(), kMm));
}

}  // namespace
}  // namespace rlpos
