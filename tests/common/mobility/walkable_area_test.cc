#include "common/mobility/walkable_area.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

// A 100 x 100 m venue with a building [40, 60] x [40, 60].
Scenario OneBuilding() {
  Scenario s;
  BuildingSpec b;
  b.xmin = 40, b.xmax = 60, b.ymin = 40, b.ymax = 60;
  s.buildings.push_back(b);
  return s;
}

TEST(WalkableArea, IsTheVenueWithoutTheFootprints) {
  const WalkableArea area(OneBuilding());
  EXPECT_TRUE(area.Contains(10, 10));
  EXPECT_FALSE(area.Contains(50, 50));
  EXPECT_FALSE(area.Contains(40, 50));  // on the wall
  EXPECT_FALSE(area.Contains(-0.1, 50));
  EXPECT_FALSE(area.Contains(50, 100.1));
}

TEST(WalkableArea, ALegThatCrossesABuildingIsBlocked) {
  const WalkableArea area(OneBuilding());
  EXPECT_TRUE(area.LegIsClear({10, 10, 0}, {90, 10, 0}));
  EXPECT_FALSE(area.LegIsClear({10, 50, 0}, {90, 50, 0}));   // straight through
  EXPECT_FALSE(area.LegIsClear({30, 55, 0}, {55, 30, 0}));   // across a corner
  EXPECT_TRUE(area.LegIsClear({30, 35, 0}, {35, 30, 0}));    // short of it
  EXPECT_FALSE(area.LegIsClear({50, 10, 0}, {50, 40, 0}));   // up to the wall
  EXPECT_FALSE(area.LegIsClear({10, 10, 0}, {110, 10, 0}));  // out of the venue
}

}  // namespace
}  // namespace rlpos
