// The memo of each channel's airtime share: a lookup gives the bits of a solve, a recurring
// channel is solved once, the memo stays within its bound, and an evaluator that remembers
// shares scores a search's placements as fresh evaluators do.
#include "worker/env/uav_env/channel_share_memo.h"

#include <gtest/gtest.h>

#include <random>

#include "common/phy/mcs_table.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

CaptureCost Capture() {
  CaptureCost capture;
  capture.contention.probability = 0.2;
  capture.follow_up_rate_mbps = 29.25;
  return capture;
}

std::vector<AirtimeLink> RandomDomain(std::mt19937_64& rng, int ues) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<AirtimeLink> domain;
  for (int i = 0; i < ues; ++i) {
    domain.push_back({5.0 + 20.0 * unit(rng), 29.25 * (1 + static_cast<int>(8 * unit(rng))),
                      0.5 + 0.5 * unit(rng), 5.0 + 40.0 * unit(rng)});
  }
  return domain;
}

TEST(ChannelShareMemo, GivesTheBitsOfASolveAndSolvesARecurringChannelOnce) {
  std::mt19937_64 rng(11);
  ChannelShareMemo memo;
  const CaptureCost capture = Capture();
  std::vector<std::vector<AirtimeLink>> domains;
  for (int d = 0; d < 40; ++d)
    domains.push_back(RandomDomain(rng, 1 + d % 12));
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto& domain : domains) {
      EXPECT_EQ(memo.Aggregate(domain, 1464, capture),
                EstimateAirtimeThroughput(domain, 1464, capture).aggregate_mbps);
    }
    EXPECT_EQ(memo.Size(), domains.size()) << "pass " << pass;  // the second pass only looks up
  }
  // One bit of one UE's SNR makes another channel state.
  std::vector<AirtimeLink> nudged = domains[5];
  nudged[0].snr_db = std::nextafter(nudged[0].snr_db, 100.0);
  EXPECT_EQ(memo.Aggregate(nudged, 1464, capture),
            EstimateAirtimeThroughput(nudged, 1464, capture).aggregate_mbps);
  EXPECT_EQ(memo.Size(), domains.size() + 1);
}

TEST(ChannelShareMemo, StartsAgainEmptyWhenItsKeysFillTheirBudget) {
  ChannelShareMemo memo;
  const CaptureCost capture = Capture();
  // Channels of ten UEs: 40 key words each.
  const std::size_t fit = ChannelShareMemo::kMaxKeyWords / 40;
  for (std::size_t i = 0; i <= fit; ++i) {
    std::vector<AirtimeLink> ten(10, {20.0, 29.25, 1.0, 20.0});
    ten[0].demand_mbps = 1.0 + static_cast<double>(i);
    memo.Aggregate(ten, 1464, capture);
    ASSERT_LE(memo.KeyWords(), ChannelShareMemo::kMaxKeyWords);
    ASSERT_EQ(memo.KeyWords(), 40 * memo.Size());
  }
  EXPECT_EQ(memo.Size(), 1u);  // the last one, after the memo started again
}

// One UAV of campus2 (two UAVs on channels of their own) swept over a grid while the other
// stands: one evaluator scores every point from its memo of shares as a fresh one does.
TEST(ChannelShareMemo, AnEvaluatorThatRemembersSharesScoresASweepAsFreshOnesDo) {
  const Scenario s =
      LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json",
                   {"env.fidelity=analytic"});
  ASSERT_EQ(s.uavs.size(), 2u);
  AnalyticEvaluator remembering(s);
  const Placement start = s.InitialPlacement();
  const std::vector<UeLink> still = remembering.LinksAt(1, start[1]);
  int points = 0;
  for (double dx = -60; dx <= 60; dx += 20) {
    for (double dy = -60; dy <= 60; dy += 20) {
      Placement p = start;
      p[0].x += dx;
      p[0].y += dy;
      const std::vector<UeLink> moved = remembering.LinksAt(0, p[0]);
      const StepInfo warm = remembering.Score(p, {&moved, &still});
      AnalyticEvaluator fresh(s);
      const StepInfo cold = fresh.Score(p, {&moved, &still});
      EXPECT_EQ(warm.throughput_mbps, cold.throughput_mbps) << dx << ", " << dy;
      EXPECT_EQ(warm.serving, cold.serving) << dx << ", " << dy;
      ++points;
    }
  }
  EXPECT_EQ(points, 49);
}

}  // namespace
}  // namespace rlpos
