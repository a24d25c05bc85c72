#include "common/phy/dcf_contention.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rlpos {
namespace {

TEST(DcfContention, AloneThereIsOnlyTheMeanBackoff) {
  const DcfContention c = SaturatedDcf(1);
  EXPECT_NEAR(c.tau, 2.0 / 17, 1e-12);  // uniform backoff in [0, 15]: one slot in 8.5
  EXPECT_NEAR(c.collision_probability, 0.0, 1e-12);
  EXPECT_NEAR(c.idle_slots_per_success, 7.5, 1e-9);
  EXPECT_NEAR(c.collisions_per_success, 0.0, 1e-12);
  // Fewer than one contender is still one.
  EXPECT_NEAR(SaturatedDcf(0.3).idle_slots_per_success, 7.5, 1e-9);
}

TEST(DcfContention, SolvesBianchisFixedPoint) {
  for (double n : {2.0, 5.0, 20.0, 50.0}) {
    const DcfContention c = SaturatedDcf(n);
    // p = 1 - (1 - tau)^(n-1) ...
    EXPECT_NEAR(c.collision_probability, 1 - std::pow(1 - c.tau, n - 1), 1e-9) << n;
    // ... and tau from Bianchi's closed form (W = 16, m = 6 stages up to CW 1023).
    const double p = c.collision_probability, w = 16;
    const double tau = 2 * (1 - 2 * p) / ((1 - 2 * p) * (w + 1) + p * w * (1 - std::pow(2 * p, 6)));
    EXPECT_NEAR(c.tau, tau, 1e-9) << n;
  }
}

TEST(DcfContention, CrowdsCollideMoreAndIdleLess) {
  double last_collisions = 0.0, last_idle = 1e9;
  for (double n : {1.0, 2.0, 4.0, 10.0, 20.0}) {
    const DcfContention c = SaturatedDcf(n);
    EXPECT_GE(c.collisions_per_success, last_collisions) << n;
    EXPECT_LT(c.idle_slots_per_success, last_idle) << n;
    last_collisions = c.collisions_per_success;
    last_idle = c.idle_slots_per_success;
  }
  // Twenty saturated best-effort stations: nearly one transmission in two collides.
  const DcfContention twenty = SaturatedDcf(20);
  EXPECT_GT(twenty.collision_probability, 0.4);
  EXPECT_LT(twenty.collision_probability, 0.55);
  EXPECT_GT(twenty.collisions_per_success, 0.3);
}

TEST(DcfContention, LargerWindowsCollideLess) {
  EXPECT_LT(SaturatedDcf(20, 31, 1023).collision_probability,
            SaturatedDcf(20, 15, 1023).collision_probability);
}

}  // namespace
}  // namespace rlpos
