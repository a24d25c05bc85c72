// The LoS rule the generator relies on (boxes, as its styles draw them), and the UEs it hides.
#include "common/scenario_generator/hidden_ues.h"

#include <gtest/gtest.h>

#include "common/geometry/obstacles.h"

namespace rlpos {
namespace {

const Box kTower{45, 55, 45, 55, 0, 20};

bool SegmentMeetsBox(const Vec3& a, const Vec3& b, const Box& box) {
  return Obstacles({Solid::OfBox(box)}).Blocked(a, b);
}

TEST(BoxLos, ThroughTheMiddleIsBlocked) {
  EXPECT_TRUE(SegmentMeetsBox({30, 50, 1.5}, {70, 50, 1.5}, kTower));
  EXPECT_TRUE(SegmentMeetsBox({50, 50, 25}, {70, 50, 1.5}, kTower));  // from above the roof
}

TEST(BoxLos, BesideAboveAndShortOfTheBoxIsClear) {
  EXPECT_FALSE(SegmentMeetsBox({30, 40, 1.5}, {70, 40, 1.5}, kTower));  // passes beside
  EXPECT_FALSE(SegmentMeetsBox({30, 50, 30}, {70, 50, 25}, kTower));    // passes above
  EXPECT_FALSE(SegmentMeetsBox({30, 50, 1.5}, {44, 50, 1.5}, kTower));  // stops short
  // Diagonal past the corner: the box's axes overlap the segment's, only a cross axis separates.
  EXPECT_FALSE(SegmentMeetsBox({38, 60, 5}, {60, 38, 5}, {45, 55, 55.5, 60, 0, 20}));
}

TEST(BoxLos, GrazingAWallOrStartingInsideCounts) {
  EXPECT_TRUE(SegmentMeetsBox({30, 45, 1.5}, {70, 45, 1.5}, kTower));  // along the wall
  EXPECT_TRUE(SegmentMeetsBox({50, 50, 5}, {90, 90, 5}, kTower));      // starts inside
}

TEST(BoxLos, OverTheRoofFromAUavJustAboveIt) {
  // A UAV 5 m above the tower's centre, a UE 1 m from its east wall: the roof is in the way.
  EXPECT_TRUE(SegmentMeetsBox({50, 50, 25}, {56, 50, 1.5}, kTower));
  // A UE 44 m from the wall sees the UAV over the roof's edge (22.6 m up there).
  EXPECT_FALSE(SegmentMeetsBox({50, 50, 25}, {99, 50, 1.5}, kTower));
}

TEST(HiddenUes, UesHiddenFromAllCountsUesNoUavSees) {
  Scenario s;
  BuildingSpec wall;
  wall.xmin = 45;
  wall.xmax = 55;
  wall.ymin = 0;
  wall.ymax = 100;
  wall.height = 30;
  s.buildings = {wall};
  UeSpec east, west;
  east.position = {80, 50, 1.5};
  west.position = {20, 50, 1.5};
  s.ues = {east, west};
  EXPECT_EQ(UesHiddenFromAll(s, {{20, 50, 10}}), 1);
  EXPECT_EQ(UesHiddenFromAll(s, {{20, 50, 10}, {80, 50, 10}}), 0);
  EXPECT_EQ(UesHiddenFromAll(s, {{50, 50, 35}}), 2);
}

}  // namespace
}  // namespace rlpos
