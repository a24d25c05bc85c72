// A UAV's flight in one interval: straight toward its target within both speed limits, inside its
// zone, never into a building or another UAV.
#include "worker/positioning/track/uav_flight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rlpos {
namespace {

Scenario Open() {
  Scenario s;
  s.ues.push_back({});
  s.uavs[0].max_speed = 10.0;
  s.uavs[0].max_climb = 3.0;
  return s;
}

double Horizontal(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

TEST(UavFlight, NeverFasterThanEitherLimit) {
  const Scenario s = Open();
  const Vec3 from{10, 10, 10};
  for (const Vec3 target :
       {Vec3{90, 80, 50}, Vec3{90, 10, 10}, Vec3{10, 10, 60}, Vec3{12, 11, 2}}) {
    const Vec3 to = FlyToward(s, 0, {from}, target, 0.5);
    EXPECT_LE(Horizontal(from, to), 10.0 * 0.5 + 1e-9);
    EXPECT_LE(std::abs(to.z - from.z), 3.0 * 0.5 + 1e-9);
  }
}

TEST(UavFlight, FliesTheStraightLineAndStopsAtTheTarget) {
  const Scenario s = Open();
  // 40 m across and 3 m up: horizontal speed binds (1 s: 10 m), a quarter of the way.
  const Vec3 to = FlyToward(s, 0, {{10, 10, 10}}, {50, 10, 13}, 1.0);
  EXPECT_NEAR(to.x, 20.0, 1e-9);
  EXPECT_NEAR(to.z, 10.75, 1e-9);
  // Climb binds: 30 m up at 3 m/s, 4 m across: a tenth of the way.
  const Vec3 up = FlyToward(s, 0, {{10, 10, 10}}, {14, 10, 40}, 1.0);
  EXPECT_NEAR(up.z, 13.0, 1e-9);
  EXPECT_NEAR(up.x, 10.4, 1e-9);
  // Within reach: there, not beyond.
  const Vec3 there = FlyToward(s, 0, {{10, 10, 10}}, {13, 14, 11}, 1.0);
  EXPECT_EQ(there.x, 13.0);
  EXPECT_EQ(there.y, 14.0);
  EXPECT_EQ(there.z, 11.0);
}

TEST(UavFlight, StaysInItsZone) {
  Scenario s = Open();
  s.uavs[0].zone = {0, 50, 0, 50, 5, 30};
  const Vec3 to = FlyToward(s, 0, {{49, 49, 29}}, {80, 80, 60}, 1.0);
  EXPECT_LE(to.x, 50.0);
  EXPECT_LE(to.y, 50.0);
  EXPECT_LE(to.z, 30.0);
}

TEST(UavFlight, ClimbsOverABuildingInsteadOfEnteringIt) {
  Scenario s = Open();
  BuildingSpec b;
  b.xmin = 20, b.xmax = 30, b.ymin = 0, b.ymax = 100, b.height = 20;
  s.buildings.push_back(b);
  Placement now{{15, 50, 10}};
  for (int i = 0; i < 40; ++i) {
    const Vec3 next = FlyToward(s, 0, now, {40, 50, 10}, 1.0);
    // Every point of the leg is outside the building.
    for (double f = 0; f <= 1.0; f += 0.01) {
      const Vec3 p{now[0].x + (next.x - now[0].x) * f, now[0].y + (next.y - now[0].y) * f,
                   now[0].z + (next.z - now[0].z) * f};
      ASSERT_FALSE(p.x >= 20 && p.x <= 30 && p.z <= 20) << "step " << i << " at " << p.x;
    }
    now[0] = next;
  }
  EXPECT_NEAR(now[0].x, 40.0, 1e-9) << "it got past the building";
  EXPECT_NEAR(now[0].z, 10.0, 1e-9) << "and came down to its target";
}

TEST(UavFlight, HoldsRatherThanFlyIntoAnotherUav) {
  Scenario s = Open();
  s.uavs.push_back(s.uavs[0]);
  s.uavs[1].name = "uav2";
  const Placement now{{10, 10, 10}, {10.5, 10, 10}};
  const Vec3 to = FlyToward(s, 0, now, {10.8, 10, 10}, 1.0);
  EXPECT_GE(std::hypot(to.x - 10.5, to.y - 10, to.z - 10), kMinUavSeparation);
}

}  // namespace
}  // namespace rlpos
