// Points, segments and prisms against footprints: the boundary counts as inside, a courtyard is
// outside, and a segment that only grazes a wall or a corner meets the building.
#include <gtest/gtest.h>

#include "common/geometry/footprint.h"
#include "tests/common/geometry/shapes.h"

namespace rlpos {
namespace {

using test_shapes::Courtyard;
using test_shapes::LShape;

TEST(Contains, EdgesVerticesAndHoles) {
  const Footprint l{LShape(), {}};
  EXPECT_TRUE(Contains(l, {2, 2}));
  EXPECT_TRUE(Contains(l, {0, 0}));    // a vertex
  EXPECT_TRUE(Contains(l, {4, 4}));    // the reflex vertex
  EXPECT_TRUE(Contains(l, {7, 4}));    // on an edge
  EXPECT_TRUE(Contains(l, {0, 7}));    // on an edge
  EXPECT_FALSE(Contains(l, {7, 7}));   // in the notch
  EXPECT_FALSE(Contains(l, {-1, 2}));  // left of it, level with it
  EXPECT_FALSE(Contains(l, {11, 0}));  // on the line of an edge, past its end
  const Footprint c = Courtyard();
  EXPECT_TRUE(Contains(c, {2, 10}));
  EXPECT_FALSE(Contains(c, {10, 10}));  // in the courtyard
  EXPECT_TRUE(Contains(c, {5, 10}));    // on the courtyard's wall
  EXPECT_TRUE(Contains(c, {15, 15}));   // on its corner
}

TEST(SegmentMeets, CourtyardWallsAndCorners) {
  const Footprint c = Courtyard();
  // Across the courtyard without touching its walls: clear.
  EXPECT_FALSE(SegmentMeets(c, {6, 6}, {14, 14}));
  EXPECT_FALSE(SegmentMeets(c, {6, 14}, {14, 6}));
  // From the courtyard out through a wall, or up to it.
  EXPECT_TRUE(SegmentMeets(c, {10, 10}, {30, 10}));
  EXPECT_TRUE(SegmentMeets(c, {10, 10}, {15, 10}));
  // From outside: past it, onto a corner, along a wall, through a corner only.
  EXPECT_FALSE(SegmentMeets(c, {-5, -1}, {25, -1}));
  EXPECT_TRUE(SegmentMeets(c, {-5, -5}, {0, 0}));
  EXPECT_TRUE(SegmentMeets(c, {-5, 0}, {25, 0}));
  EXPECT_TRUE(SegmentMeets(c, {-5, 5}, {5, -5}));  // grazes the corner (0, 0)
  EXPECT_FALSE(SegmentMeets(c, {-5, 4.999}, {4.999, -5}));
  // Wholly inside the building's walls.
  EXPECT_TRUE(SegmentMeets(c, {1, 1}, {2, 2}));
  // An L: across its notch clear of it; across its arms; from the notch onto the reflex corner;
  // from one outer corner to the other.
  const Footprint l{LShape(), {}};
  EXPECT_FALSE(SegmentMeets(l, {5, 11}, {11, 5}));
  EXPECT_TRUE(SegmentMeets(l, {2, 6}, {6, 2}));
  EXPECT_TRUE(SegmentMeets(l, {8, 8}, {4, 4}));
  EXPECT_FALSE(SegmentMeets(l, {8, 8}, {4.01, 4.01}));
  EXPECT_TRUE(SegmentMeets(l, {10, 4}, {4, 10}));
}

TEST(SegmentMeetsPrism, Heights) {
  const Footprint c = Courtyard();
  // Level with the roof, over it: meets; above: clear.
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {-5, 2, 10}, {25, 2, 10}));
  EXPECT_FALSE(SegmentMeetsPrism(c, 0, 10, {-5, 2, 10.01}, {25, 2, 10.01}));
  // Under a part that starts at 3 m: clear at 2 m, meets at 3 m.
  EXPECT_FALSE(SegmentMeetsPrism(c, 3, 10, {-5, 2, 2}, {25, 2, 2}));
  EXPECT_TRUE(SegmentMeetsPrism(c, 3, 10, {-5, 2, 3}, {25, 2, 3}));
  // Slanted: over the near wall, down into the courtyard, out before the far wall's height.
  EXPECT_FALSE(SegmentMeetsPrism(c, 0, 10, {2, 10, 14}, {10, 10, 6}));
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {2, 10, 13}, {10, 10, 5}));  // grazes the wall's top
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {2, 10, 9}, {10, 10, 4}));
  // Slanted, reaching the roof's height only past the building.
  EXPECT_FALSE(SegmentMeetsPrism(c, 0, 10, {25, 2, 10}, {45, 2, 0}));
  // Down onto the roof's edge: meets at its last point.
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {-10, 2, 20}, {0, 2, 10}));
  // Vertical: a column in the walls, one in the courtyard, one above the roof.
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {2, 2, 0}, {2, 2, 30}));
  EXPECT_FALSE(SegmentMeetsPrism(c, 0, 10, {10, 10, 0}, {10, 10, 30}));
  EXPECT_FALSE(SegmentMeetsPrism(c, 0, 10, {2, 2, 11}, {2, 2, 30}));
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {2, 2, 10}, {2, 2, 30}));
  // A point.
  EXPECT_TRUE(SegmentMeetsPrism(c, 0, 10, {2, 2, 5}, {2, 2, 5}));
}

}  // namespace
}  // namespace rlpos
