#include "common/phy/airtime_model.h"

#include <gtest/gtest.h>

#include <vector>

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

TEST(AirtimeModel, FullAccessRespectsTheAggregationLimits) {
  EXPECT_EQ(MpduBytes(1400), 1464);
  // MCS 9 at 160 MHz: the 65535-byte A-MPDU limit (44 MPDUs); MCS 0: the 5.484 ms PPDU limit.
  EXPECT_DOUBLE_EQ(FullAccess(780, 1400).mpdus, 44);
  EXPECT_DOUBLE_EQ(FullAccess(58.5, 1400).mpdus, 27);
  EXPECT_LT(FullAccess(58.5, 1400).ppdu_us, 5484 + 40 + 1e-9);
  EXPECT_NEAR(FullAccess(780, 1400, 0.25).delivered_mbit,
              0.25 * FullAccess(780, 1400).delivered_mbit, 1e-12);
}

TEST(AirtimeModel, UnsaturatedChannelCarriesEveryDemand) {
  const auto e = EstimateAirtimeThroughput({{58.5, 780}, {58.5, 526.5}, {10, 0}}, 1400);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[0], 58.5);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[1], 58.5);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[2], 0.0);  // no link
  EXPECT_DOUBLE_EQ(e.aggregate_mbps, 117.0);
  EXPECT_LT(e.airtime_demanded, 1.0);
  // At a load of a fifth of the channel the other station is rarely there to collide with.
  EXPECT_GT(e.contenders, 1.0);
  EXPECT_LT(e.contenders, 1.5);
}

TEST(AirtimeModel, SaturatedStationsGetEqualAccesses) {
  // DCF gives backlogged stations equal transmit opportunities, each a full A-MPDU: throughputs
  // are in the ratio of what one A-MPDU carries, and the slow one holds the channel longest.
  const auto e = EstimateAirtimeThroughput({{1000, 780}, {1000, 58.5}}, 1400);
  const Access fast = FullAccess(780, 1400), slow = FullAccess(58.5, 1400);
  EXPECT_NEAR(e.throughput_mbps[0] / e.throughput_mbps[1],
              fast.delivered_mbit / slow.delivered_mbit, 1e-6);
  EXPECT_NEAR(e.contenders, 2.0, 1e-12);
  // The performance anomaly: the fast station ends far below what it carries alone.
  const auto alone = EstimateAirtimeThroughput({{1000, 780}}, 1400);
  EXPECT_NEAR(alone.aggregate_mbps, 780 * MacEfficiency(780, 1400), 1e-6);
  EXPECT_LT(e.throughput_mbps[0], 0.3 * alone.aggregate_mbps);
}

TEST(AirtimeModel, ContentionCostsACrowdedChannel) {
  // Twenty saturated stations at one rate: the accesses are shared, but collisions waste a share
  // of the channel that one station alone would not.
  const std::vector<AirtimeLink> crowd(20, AirtimeLink{1000, 780});
  const auto e = EstimateAirtimeThroughput(crowd, 1400);
  const double alone = EstimateAirtimeThroughput({{1000, 780}}, 1400).aggregate_mbps;
  EXPECT_NEAR(e.contenders, 20.0, 1e-12);
  EXPECT_LT(e.aggregate_mbps, 0.85 * alone);
  EXPECT_GT(e.aggregate_mbps, 0.5 * alone);
  EXPECT_NEAR(e.throughput_mbps[0], e.throughput_mbps[19], 1e-9);
}

TEST(AirtimeModel, LostMpdusCostAirtime) {
  const double clean = EstimateAirtimeThroughput({{1000, 780, 1.0}}, 1400).aggregate_mbps;
  const double lossy = EstimateAirtimeThroughput({{1000, 780, 0.6}}, 1400).aggregate_mbps;
  EXPECT_NEAR(lossy, 0.6 * clean, 1e-9);
  // A link that loses every MPDU carries nothing and does not contend.
  const auto dead = EstimateAirtimeThroughput({{1000, 780, 0.0}, {100, 780, 1.0}}, 1400);
  EXPECT_DOUBLE_EQ(dead.throughput_mbps[0], 0.0);
  EXPECT_DOUBLE_EQ(dead.throughput_mbps[1], 100.0);
}

TEST(AirtimeModel, SmallDemandsAreMetBeforeSharing) {
  const auto e = EstimateAirtimeThroughput({{5, 58.5}, {1000, 780}, {1000, 780}}, 1400);
  EXPECT_NEAR(e.throughput_mbps[0], 5.0, 1e-6);
  EXPECT_NEAR(e.throughput_mbps[1], e.throughput_mbps[2], 1e-6);
  EXPECT_GT(e.throughput_mbps[1], 5.0);
}

CaptureCost Capture(double probability) {
  CaptureCost cost;
  cost.contention.probability = probability;
  cost.follow_up_rate_mbps = 58.5;
  return cost;
}

std::vector<AirtimeLink> Crowd(const std::vector<double>& snr_db) {
  std::vector<AirtimeLink> links;
  for (double snr : snr_db)
    links.push_back({1000, 780, 1.0, snr});
  return links;
}

TEST(AirtimeModel, CaptureNeedsUnequalStations) {
  const auto equal = Crowd(std::vector<double>(20, 30.0));
  const auto plain = EstimateAirtimeThroughput(equal, 1400);
  const auto with_capture = EstimateAirtimeThroughput(equal, 1400, Capture(0.35));
  EXPECT_NEAR(with_capture.aggregate_mbps, plain.aggregate_mbps, 1e-9);
}

TEST(AirtimeModel, SpreadSnrsFavourTheStrongAndCostTheAggregate) {
  // The same rate for everyone: without capture the SNRs would not matter at all.
  std::vector<double> snr(20, 30.0);
  for (int i = 0; i < 5; ++i)
    snr[i] = 38.0;
  const auto spread = EstimateAirtimeThroughput(Crowd(snr), 1400, Capture(0.35));
  const auto equal =
      EstimateAirtimeThroughput(Crowd(std::vector<double>(20, 30.0)), 1400, Capture(0.35));
  EXPECT_LT(spread.aggregate_mbps, 0.95 * equal.aggregate_mbps);
  EXPECT_GT(spread.throughput_mbps[0], 1.2 * spread.throughput_mbps[19]);
  EXPECT_NEAR(spread.throughput_mbps[0], spread.throughput_mbps[4], 1e-9);
  // No capture model, no effect.
  const auto ignored = EstimateAirtimeThroughput(Crowd(snr), 1400);
  EXPECT_NEAR(ignored.throughput_mbps[0], ignored.throughput_mbps[19], 1e-9);
}

TEST(AirtimeModel, LightLoadLeavesMetDemandsMet) {
  const std::vector<AirtimeLink> links = {{20, 780, 1.0, 40}, {20, 780, 1.0, 20}};
  const auto e = EstimateAirtimeThroughput(links, 1400, Capture(1.0));
  EXPECT_DOUBLE_EQ(e.throughput_mbps[0], 20.0);
  EXPECT_DOUBLE_EQ(e.throughput_mbps[1], 20.0);
}

}  // namespace
}  // namespace rlpos
