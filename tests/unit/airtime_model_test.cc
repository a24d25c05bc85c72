#include "metrics/airtime_model.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

TEST(AirtimeModel, EfficiencyFallsWithRate) {
  const double slow = MacEfficiency(58.5, 1400);
  const double fast = MacEfficiency(780.0, 1400);
  EXPECT_GT(slow, 0.85);
  EXPECT_LT(slow, 1.0);
  EXPECT_LT(fast, slow);
  EXPECT_GT(fast, 0.5);
  EXPECT_EQ(MacEfficiency(0.0, 1400), 0.0);
}

TEST(AirtimeModel, UnsaturatedChannelCarriesEveryDemand) {
  const auto e = EstimateAirtimeThroughput({{58.5, 780}, {58.5, 526.5}, {10, 0}}, 1400);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[0], 58.5);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[1], 58.5);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[2], 0.0);  // no link
  EXPECT_DOUBLE_EQ(e.aggregate_mbps, 117.0);
  EXPECT_LT(e.airtime_demanded, 1.0);
}

TEST(AirtimeModel, SaturatedChannelIsSharedFairly) {
  // Two UEs wanting 1000 Mbit/s each, capacities c1, c2: equal shares T with T/c1 + T/c2 = 1.
  const auto e = EstimateAirtimeThroughput({{1000, 780}, {1000, 58.5}}, 1400);
  const double c1 = 780 * MacEfficiency(780, 1400);
  const double c2 = 58.5 * MacEfficiency(58.5, 1400);
  const double share = 1.0 / (1.0 / c1 + 1.0 / c2);
  EXPECT_NEAR(e.throughput_mbps[0], share, 1e-6);
  EXPECT_NEAR(e.throughput_mbps[1], share, 1e-6);
  // The slow station drags the fast one below its own capacity: the performance anomaly.
  EXPECT_LT(e.aggregate_mbps, c1);
}

TEST(AirtimeModel, SmallDemandsAreMetBeforeSharing) {
  const auto e = EstimateAirtimeThroughput({{5, 58.5}, {1000, 780}, {1000, 780}}, 1400);
  EXPECT_NEAR(e.throughput_mbps[0], 5.0, 1e-6);
  EXPECT_NEAR(e.throughput_mbps[1], e.throughput_mbps[2], 1e-6);
  EXPECT_GT(e.throughput_mbps[1], 5.0);
}

}  // namespace
}  // namespace rlpos
