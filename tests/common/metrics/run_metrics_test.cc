#include "common/metrics/run_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rlpos {
namespace {

TEST(FlowAccumulator, CountsOnlyTheWindow) {
  FlowAccumulator flow({1.0, 3.0});
  flow.OnSent(0.5);  // before the window: ignored
  flow.OnSent(1.5);
  flow.OnSent(2.5);
  flow.OnSent(2.9);
  flow.OnReceived(0.5, 1.1, 1000);  // received in window, sent before: counts for throughput
  flow.OnReceived(1.5, 1.6, 1000);
  flow.OnReceived(2.9, 3.2, 1000);  // arrives after the window: delivered, not throughput
  EXPECT_EQ(flow.SentInWindow(), 3u);
  EXPECT_EQ(flow.ReceivedInWindow(), 2u);
  EXPECT_DOUBLE_EQ(flow.ThroughputMbps(), 2000 * 8 / 2.0 / 1e6);
  EXPECT_NEAR(flow.MeanDelayMs(), (600.0 + 100.0) / 2, 1e-9);
  EXPECT_NEAR(flow.LossRatio(), 1.0 / 3.0, 1e-12);  // 2.5 never arrived
}

TEST(FlowAccumulator, UndefinedWithoutPackets) {
  FlowAccumulator flow({0.0, 1.0});
  EXPECT_TRUE(std::isnan(flow.MeanDelayMs()));
  EXPECT_TRUE(std::isnan(flow.LossRatio()));
  EXPECT_DOUBLE_EQ(flow.ThroughputMbps(), 0.0);
}

TEST(Summarize, AggregatesArePacketWeighted) {
  const MeasurementWindow window{0.0, 1.0};
  std::vector<FlowAccumulator> flows(2, FlowAccumulator(window));
  flows[0].OnSent(0.1);
  flows[0].OnReceived(0.1, 0.2, 500);  // 100 ms
  for (int i = 0; i < 3; ++i) {
    flows[1].OnSent(0.3);
    flows[1].OnReceived(0.3, 0.31, 500);  // 10 ms each
  }
  std::vector<UeMetrics> ues(2);
  ues[0].los = true;
  ues[0].snr_db = 30;
  ues[0].demand.met = true;
  ues[1].snr_db = 5;
  const RunMetrics m = Summarize({1, 2, 3}, window, 7, flows, ues);
  EXPECT_DOUBLE_EQ(m.aggregate_throughput_mbps, 2000 * 8 / 1e6);
  EXPECT_NEAR(m.mean_delay_ms, (100.0 + 3 * 10.0) / 4, 1e-9);
  EXPECT_EQ(m.n_los, 1);
  EXPECT_EQ(m.demands_met, 1);
  EXPECT_DOUBLE_EQ(m.min_snr_db, 5.0);
  EXPECT_DOUBLE_EQ(m.loss_ratio, 0.0);
  EXPECT_EQ(ToJson(m)["n_ues"], 2);
  // UE throughputs 500 and 1500 bytes/s x 8: the worst is 0.004 Mbit/s; Jain's index
  // (4 + 12)^2 / (2 (4^2 + 12^2)) = 256 / 320 = 0.8.
  EXPECT_DOUBLE_EQ(m.worst_ue_throughput_mbps, 500 * 8 / 1e6);
  EXPECT_NEAR(m.jain_fairness, 0.8, 1e-12);
  EXPECT_NEAR(ToJson(m)["jain_fairness"].get<double>(), 0.8, 1e-12);
}

TEST(Summarize, PerUavSharesAddUpAndFollowTheServingUav) {
  const MeasurementWindow window{0.0, 1.0};
  // UEs 0 and 2 at UAV "a", UE 1 at UAV "b"; UAV "c" serves nobody.
  std::vector<FlowAccumulator> flows(3, FlowAccumulator(window));
  flows[0].OnSent(0.1);
  flows[0].OnReceived(0.1, 0.12, 1000);  // 20 ms
  flows[1].OnSent(0.2);
  flows[1].OnReceived(0.2, 0.21, 3000);  // 10 ms
  flows[2].OnSent(0.3);
  flows[2].OnSent(0.4);
  flows[2].OnReceived(0.3, 0.34, 3000);  // 40 ms; one of two lost
  std::vector<UeMetrics> ues(3);
  ues[0].uav = 0;
  ues[0].los = true;
  ues[1].uav = 1;
  ues[1].los = true;
  ues[2].uav = 0;
  const RunMetrics m =
      Summarize({{"a", {1, 1, 10}, 50}, {"b", {9, 9, 10}, 114}, {"c", {5, 5, 20}, 42}}, window, 1,
                flows, ues);
  ASSERT_EQ(m.uavs.size(), 3u);
  const UavMetrics& a = m.uavs[0];
  EXPECT_EQ(a.uav.name, "a");
  EXPECT_EQ(a.uav.channel, 50);
  EXPECT_EQ(a.ues_served, 2);
  EXPECT_DOUBLE_EQ(a.throughput_mbps, 4000 * 8 / 1e6);
  EXPECT_NEAR(a.mean_delay_ms, 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(a.loss_ratio, 1.0 / 3);
  EXPECT_EQ(a.n_los, 1);
  EXPECT_DOUBLE_EQ(a.worst_ue_throughput_mbps, 1000 * 8 / 1e6);
  // (1 + 3)^2 / (2 (1 + 9)) = 0.8
  EXPECT_NEAR(a.jain_fairness, 0.8, 1e-12);
  EXPECT_EQ(m.uavs[1].ues_served, 1);
  EXPECT_DOUBLE_EQ(m.uavs[1].throughput_mbps, 3000 * 8 / 1e6);
  EXPECT_NEAR(m.uavs[1].jain_fairness, 1.0, 1e-12);
  EXPECT_EQ(m.uavs[2].ues_served, 0);
  EXPECT_DOUBLE_EQ(m.uavs[2].throughput_mbps, 0.0);
  EXPECT_TRUE(std::isnan(m.uavs[2].jain_fairness));
  EXPECT_TRUE(std::isnan(m.uavs[2].worst_ue_throughput_mbps));
  EXPECT_DOUBLE_EQ(m.aggregate_throughput_mbps, a.throughput_mbps + m.uavs[1].throughput_mbps);
  EXPECT_EQ(m.n_los, 2);
  EXPECT_DOUBLE_EQ(m.position.x, 1.0);  // the first UAV's
  const auto j = ToJson(m);
  ASSERT_EQ(j["uavs"].size(), 3u);
  EXPECT_EQ(j["uavs"][1]["ues_served"], 1);
  EXPECT_TRUE(j["uavs"][2]["jain_fairness"].is_null());
  EXPECT_EQ(j["ues"][2]["uav"], "a");
  // One UAV: no "uavs" (they would repeat the run's metrics).
  EXPECT_FALSE(ToJson(Summarize({1, 2, 3}, window, 1, flows, ues))["ues"][0].contains("uav"));
  EXPECT_FALSE(ToJson(Summarize({1, 2, 3}, window, 1, flows, ues)).contains("uavs"));
}

TEST(Summarize, JainIndexSpansOneOverNToOne) {
  EXPECT_DOUBLE_EQ(JainIndex({3, 3, 3}), 1.0);
  EXPECT_DOUBLE_EQ(JainIndex({5, 0, 0, 0}), 0.25);  // one UE of four gets everything
  EXPECT_TRUE(std::isnan(JainIndex({0, 0})));       // nothing received: undefined
  EXPECT_TRUE(std::isnan(JainIndex({})));
}

TEST(CheckDemand, MapsDemandToMcsToSnr) {
  const PhyProfile phy{"802.11ac", 160, 800, 1};
  const DemandCheck c = CheckDemand(phy, 234.0, 16.9);
  EXPECT_EQ(c.required_mcs, 3);
  EXPECT_DOUBLE_EQ(c.min_snr_db, 17.0);
  EXPECT_FALSE(c.met);
  EXPECT_TRUE(CheckDemand(phy, 234.0, 17.0).met);
  EXPECT_FALSE(CheckDemand(phy, 5000.0, 99.0).met);
}

}  // namespace
}  // namespace rlpos
