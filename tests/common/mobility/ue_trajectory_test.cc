#include "common/mobility/ue_trajectory.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace rlpos {
namespace {

TEST(UeTrajectory, IsLinearBetweenWaypointsAndHeldOutside) {
  const UeTrajectory t({{1.0, {0, 0, 1.5}}, {3.0, {4, 2, 1.5}}, {5.0, {4, 2, 1.5}}});
  EXPECT_DOUBLE_EQ(t.PositionAt(0.0).x, 0.0);  // before the first: its position
  EXPECT_DOUBLE_EQ(t.PositionAt(2.0).x, 2.0);
  EXPECT_DOUBLE_EQ(t.PositionAt(2.0).y, 1.0);
  EXPECT_DOUBLE_EQ(t.PositionAt(2.0).z, 1.5);
  EXPECT_DOUBLE_EQ(t.PositionAt(3.0).x, 4.0);
  EXPECT_DOUBLE_EQ(t.PositionAt(4.0).x, 4.0);   // a pause
  EXPECT_DOUBLE_EQ(t.PositionAt(99.0).y, 2.0);  // after the last: its position
  EXPECT_TRUE(t.Moves());
  EXPECT_FALSE(UeTrajectory::Still({1, 2, 3}).Moves());
}

TEST(UeTrajectory, RejectsNoWaypointsAndTimeGoingBack) {
  EXPECT_THROW(UeTrajectory({}), std::invalid_argument);
  EXPECT_THROW(UeTrajectory({{2.0, {}}, {1.0, {}}}), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
