#include "common/phy/dcf_contention.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

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

namespace rlpos {
namespace {

// Bianchi's fixed point as it was solved before the bisection stopped early and the solutions
// were memoised: all 100 bisection steps, every call.
DcfContention FullBisection(double stations, int cw_min, int cw_max) {
  const double n = std::max(1.0, stations);
  const double w = cw_min + 1.0;
  const int stages = BackoffStages(cw_min, cw_max);
  auto tau = [&](double p) {
    double sum = 0.0, term = 1.0;
    for (int k = 0; k < stages; ++k, term *= 2 * p)
      sum += term;
    return 2.0 / (1.0 + w + p * w * sum);
  };
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 100; ++k) {
    const double p = 0.5 * (lo + hi);
    const double rhs = 1.0 - std::pow(1.0 - tau(p), n - 1.0);
    (rhs > p ? lo : hi) = p;
  }
  DcfContention c;
  c.collision_probability = 0.5 * (lo + hi);
  c.tau = tau(c.collision_probability);
  const double idle = std::pow(1.0 - c.tau, n);
  const double success = n * c.tau * std::pow(1.0 - c.tau, n - 1.0);
  c.idle_slots_per_success = idle / success;
  c.collisions_per_success = (1.0 - idle - success) / success;
  return c;
}

TEST(DcfContention, SameBitsAsTheFullBisectionFirstTimeAndFromTheMemo) {
  const std::pair<int, int> windows[] = {{15, 1023}, {7, 255}, {15, 15}};
  for (double n = 0.5; n < 40; n += 0.173) {
    for (int call = 0; call < 2; ++call) {  // solved, then remembered (for each window apart)
      for (const auto& [cw_min, cw_max] : windows) {
        const DcfContention want = FullBisection(n, cw_min, cw_max);
        const DcfContention got = SaturatedDcf(n, cw_min, cw_max);
        EXPECT_EQ(got.tau, want.tau) << n << " " << cw_min << " " << cw_max;
        EXPECT_EQ(got.collision_probability, want.collision_probability) << n;
        EXPECT_EQ(got.idle_slots_per_success, want.idle_slots_per_success) << n;
        EXPECT_EQ(got.collisions_per_success, want.collisions_per_success) << n;
      }
    }
  }
}

}  // namespace
}  // namespace rlpos
