// A UAV that flies during an ns-3 run (UavMotion::kFlies): ns-3's waypoint mobility moves it
// along each leg at constant velocity, and the links follow.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "tests/worker/env/network/shipped_scenario.h"
#include "worker/env/network/uav_network.h"

namespace rlpos {
namespace {

// A position of scenario B that sees all four UEs (see docs/scenarios.md).
const Vec3 kSeesAllB{50, 35, 10};

Vec3 Between(const Vec3& a, const Vec3& b, double share) {
  return {a.x + (b.x - a.x) * share, a.y + (b.y - a.y) * share, a.z + (b.z - a.z) * share};
}

void ExpectAt(const UavNetwork& network, const Vec3& expected, const char* when) {
  const Vec3 at = network.UavPositions().front();
  EXPECT_NEAR(at.x, expected.x, 1e-6) << when;
  EXPECT_NEAR(at.y, expected.y, 1e-6) << when;
  EXPECT_NEAR(at.z, expected.z, 1e-6) << when;
}

int LosCount(const UavNetwork& network) {
  int n = 0;
  for (const LinkState& link : network.LinksTo(0))
    n += link.los ? 1 : 0;
  return n;
}

// Gives the UAV the leg `from` -> `to`, to end at `arrive`: at `halfway` it is midway, at `after`
// at `to`.
void ExpectLeg(UavNetwork& network, const Vec3& from, const Vec3& to, double halfway, double arrive,
               double after, const std::string& leg) {
  network.FlyUav(0, to, arrive);
  network.RunUntil(halfway);
  ExpectAt(network, Between(from, to, 0.5), ("halfway through the " + leg + " leg").c_str());
  network.RunUntil(after);
  ExpectAt(network, to, ("after the " + leg + " leg").c_str());
}

TEST(FlyingUav, FliesEachLegAtConstantVelocityAndTheLinksFollow) {
  const Scenario b = LoadShipped("b", {"simulation.duration=1.2"});
  const Vec3 start = b.InitialPlacement().front();
  UavNetwork network(b, {start}, Handover::kOff, UavMotion::kFlies);
  ASSERT_LT(LosCount(network), 4);
  ExpectLeg(network, start, kSeesAllB, 0.2, 0.4, 0.6, "first");
  EXPECT_EQ(LosCount(network), 4);
  // The next leg starts when it is given, not when the last one ended.
  ExpectLeg(network, kSeesAllB, start, 0.8, 1.0, 1.1, "second");
  EXPECT_LT(LosCount(network), 4);
}

TEST(FlyingUav, RefusesWhatItCannotFly) {
  const Scenario b = LoadShipped("b", {"simulation.duration=2"});
  {
    UavNetwork fixed(b, b.InitialPlacement());
    EXPECT_THROW(fixed.FlyUav(0, kSeesAllB, 1.0), std::logic_error);
  }
  UavNetwork flying(b, b.InitialPlacement(), Handover::kOff, UavMotion::kFlies);
  EXPECT_THROW(flying.SetUavPositions({kSeesAllB}), std::logic_error);
  EXPECT_THROW(flying.FlyUav(0, kSeesAllB, 0.0), std::invalid_argument);
  EXPECT_THROW(flying.FlyUav(1, kSeesAllB, 1.0), std::out_of_range);
  flying.FlyUav(0, kSeesAllB, 1.5);
  EXPECT_THROW(flying.FlyUav(0, b.InitialPlacement().front(), 1.0), std::logic_error);
}

}  // namespace
}  // namespace rlpos
