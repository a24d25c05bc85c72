// Integration tests of the scenario engine on the shipped scenarios, short durations.
#include "worker/env/network/uav_network.h"

#include <gtest/gtest.h>

#include "common/scenario/scenario_parser.h"
#include "tests/worker/env/network/shipped_scenario.h"
#include "worker/env/network/scenario_loading.h"

namespace rlpos {
namespace {

// A position of scenario B that sees all four UEs (see docs/scenarios.md, "Scenarios A, B and C").
const Vec3 kAllLosB{50, 35, 10};

TEST(UavNetwork, ScenarioBAllLosBeatsTheBaseline) {
  const Scenario s = LoadShipped("b", {"simulation.duration=3"});
  const RunMetrics baseline = EvaluatePosition(s, s.InitialPlacement());
  const RunMetrics all_los = EvaluatePosition(s, {kAllLosB});
  EXPECT_LT(baseline.n_los, 4);
  EXPECT_EQ(all_los.n_los, 4);
  EXPECT_GT(all_los.aggregate_throughput_mbps, 1.1 * baseline.aggregate_throughput_mbps);
  EXPECT_LT(all_los.mean_delay_ms, baseline.mean_delay_ms);
  // Sanity: nothing beyond the offered load.
  EXPECT_LE(all_los.aggregate_throughput_mbps, s.TotalDemandMbps() * 1.02);
  std::printf("B baseline: %.2f Mbit/s, %.3f ms; all-LoS: %.2f Mbit/s, %.3f ms\n",
              baseline.aggregate_throughput_mbps, baseline.mean_delay_ms,
              all_los.aggregate_throughput_mbps, all_los.mean_delay_ms);
}

TEST(UavNetwork, RebuildingInOneProcessGivesTheSameRun) {
  // The gym rebuilds the network every episode: the same seed and RngRun must give the same
  // events however many networks the process built before.
  const Scenario s = LoadShipped("b", {"simulation.duration=1.5", "simulation.warmup=0.5"});
  const RunMetrics first = EvaluatePosition(s, s.InitialPlacement());
  const RunMetrics second = EvaluatePosition(s, s.InitialPlacement());
  EXPECT_EQ(ToJson(first), ToJson(second));
}

TEST(UavNetwork, ObstacleAwareSnrDropsBehindABuildingHybridDoesNot) {
  // Two UAV positions 25 m from ue1 (70, 60, 1.5), 25 m up: west of it in the open, east of it
  // behind the east hall (x 72-80, 15 m tall).
  const Vec3 open{45, 60, 25};
  const Vec3 hidden{95, 60, 25};
  const Scenario ours = LoadShipped("b");
  const Scenario hybrid =
      LoadShipped("b", {"propagation={\"type\": \"ns3::HybridBuildingsPropagationLossModel\", "
                        "\"attributes\": {\"ShadowSigmaOutdoor\": 0}}"});
  auto snr = [](const Scenario& s, const Vec3& p) {
    UavNetwork network(s, {p});
    const auto links = network.Links();
    return std::make_pair(links[1].los, links[1].snr_db);
  };
  const auto ours_open = snr(ours, open);
  const auto ours_hidden = snr(ours, hidden);
  ASSERT_TRUE(ours_open.first);
  ASSERT_FALSE(ours_hidden.first);
  EXPECT_GT(ours_open.second - ours_hidden.second, 10.0);
  const auto hybrid_open = snr(hybrid, open);
  const auto hybrid_hidden = snr(hybrid, hidden);
  EXPECT_NEAR(hybrid_open.second, hybrid_hidden.second, 1e-6);
}

}  // namespace
}  // namespace rlpos
