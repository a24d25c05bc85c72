#include "common/phy/mcs_table.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

TEST(McsTable, VhtRatesMatchThePaperDemands) {
  const PhyProfile phy{"802.11ac", 160, 800, 1};
  // The paper's demands: MCS 0..3 at 160 MHz, GI 800 ns, one stream.
  EXPECT_DOUBLE_EQ(McsDataRateMbps(phy, 0), 58.5);
  EXPECT_DOUBLE_EQ(McsDataRateMbps(phy, 1), 117.0);
  EXPECT_DOUBLE_EQ(McsDataRateMbps(phy, 2), 175.5);
  EXPECT_DOUBLE_EQ(McsDataRateMbps(phy, 3), 234.0);
  EXPECT_NEAR(McsDataRateMbps(phy, 9), 780.0, 1e-9);
}

TEST(McsTable, KnownRatesOfOtherProfiles) {
  EXPECT_NEAR(McsDataRateMbps({"802.11ac", 80, 400, 1}, 9), 433.3, 0.05);
  EXPECT_NEAR(McsDataRateMbps({"802.11n", 20, 800, 1}, 7), 65.0, 1e-9);
  EXPECT_NEAR(McsDataRateMbps({"802.11n", 40, 400, 2}, 7), 300.0, 1e-9);
  EXPECT_NEAR(McsDataRateMbps({"802.11ax", 80, 800, 1}, 11), 600.5, 0.05);
  EXPECT_THROW(McsDataRateMbps({"802.11n", 20, 800, 1}, 8), std::invalid_argument);
}

TEST(McsTable, RequiredMcsIsTheLowestThatCarriesTheDemand) {
  const PhyProfile phy{"802.11ac", 160, 800, 1};
  EXPECT_EQ(RequiredMcs(phy, 58.5), 0);
  EXPECT_EQ(RequiredMcs(phy, 58.6), 1);
  EXPECT_EQ(RequiredMcs(phy, 234.0), 3);
  EXPECT_EQ(RequiredMcs(phy, 781.0), -1);
}

TEST(McsTable, MinimumSnrGrowsWithMcs) {
  for (int mcs = 1; mcs <= 11; ++mcs)
    EXPECT_GT(McsMinSnrDb(mcs), McsMinSnrDb(mcs - 1));
  EXPECT_DOUBLE_EQ(McsMinSnrDb(0), 9.0);
}

TEST(McsTable, ThermalNoise) {
  EXPECT_NEAR(ThermalNoiseDbm(20), -100.99, 0.01);
  EXPECT_NEAR(ThermalNoiseDbm(160), -91.96, 0.01);
}

}  // namespace
}  // namespace rlpos
