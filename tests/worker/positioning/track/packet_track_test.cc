// A track run at packet level: one ns-3 run in which the UEs walk and the UAVs fly the legs the
// analytic run flies, scored by the packets, the same numbers every time.
#include <gtest/gtest.h>

#include <cmath>

#include "common/config/config_error.h"
#include "common/scenario_generator/scenario_generator.h"
#include "tests/worker/positioning/track/track_test_support.h"
#include "worker/positioning/track/track_run.h"

namespace rlpos {
namespace {

using testing::Walking;

TrackResult Track(const Scenario& s, double duration, TrackFidelity fidelity) {
  auto p = MakeTrackPositioner("centroid-track", s);
  return RunTrack(s, *p, duration, fidelity);
}

std::vector<double> Series(const TrackResult& r) {
  std::vector<double> values;
  for (const TrackInterval& i : r.intervals) {
    values.insert(values.end(), {i.reward, i.throughput_mbps, i.mean_delay_ms});
    values.insert(values.end(), i.serving.begin(), i.serving.end());
    for (const Vec3& p : i.positions)
      values.insert(values.end(), {p.x, p.y, p.z});
  }
  return values;
}

TEST(PacketTrack, FliesTheAnalyticLegsScoredByThePacketsTheSameEveryTime) {
  // Two UAVs: each decision re-applies the association rule while they fly.
  Scenario s = Walking(2, 1);
  s.env.decision_interval = 0.5;
  s.simulation.warmup = 0.5;
  for (UeSpec& ue : s.ues)
    ue.demand_mbps = 2.0;  // light traffic: a short test
  const TrackResult analytic = Track(s, 2.0, TrackFidelity::kAnalytic);
  const TrackResult packet = Track(s, 2.0, TrackFidelity::kPacket);
  ASSERT_EQ(packet.intervals.size(), 4u);
  ASSERT_EQ(analytic.intervals.size(), 4u);
  double scored_reward = 0.0;
  for (std::size_t k = 0; k < packet.intervals.size(); ++k) {
    const TrackInterval& p = packet.intervals[k];
    const TrackInterval& a = analytic.intervals[k];
    // The decisions see the same UEs (ns-3's waypoints play the trajectories) and the UAVs
    // end where the analytic flight ends: ns-3 flew them there.
    for (std::size_t u = 0; u < s.uavs.size(); ++u) {
      EXPECT_NEAR(p.targets[u].x, a.targets[u].x, 1e-6) << p.time;
      EXPECT_NEAR(p.targets[u].y, a.targets[u].y, 1e-6) << p.time;
      EXPECT_NEAR(p.positions[u].x, a.positions[u].x, 1e-6) << p.time;
      EXPECT_NEAR(p.positions[u].y, a.positions[u].y, 1e-6) << p.time;
      EXPECT_NEAR(p.positions[u].z, a.positions[u].z, 1e-6) << p.time;
    }
    const bool in_warmup = p.time - s.env.decision_interval < s.simulation.warmup;
    EXPECT_EQ(p.scored, !in_warmup) << p.time;
    EXPECT_TRUE(a.scored) << "the analytic model has no warm-up";
    if (p.scored) {
      scored_reward += p.reward;
      EXPECT_GT(p.throughput_mbps, 0.0) << p.time;
      EXPECT_TRUE(std::isfinite(p.mean_delay_ms)) << p.time;
    }
    EXPECT_TRUE(std::isnan(a.mean_delay_ms));
  }
  EXPECT_GT(packet.metrics.distance_flown_m, 0.0) << "the UAVs never followed";
  EXPECT_DOUBLE_EQ(packet.metrics.mean_reward, scored_reward / 3);
  EXPECT_NEAR(packet.metrics.distance_flown_m, analytic.metrics.distance_flown_m, 1e-9);

  const TrackResult again = Track(s, 2.0, TrackFidelity::kPacket);
  EXPECT_EQ(Series(packet), Series(again));
  EXPECT_EQ(packet.metrics.mean_reward, again.metrics.mean_reward);
}

TEST(PacketTrack, AUeThatMissesItsUavsBeaconsStaysInItsBss) {
  // Held-out urban s91000, its UEs on random waypoints: at about 4.5 s a UE misses enough of
  // the flying UAV's beacons that ns-3.37 would disassociate it, flush its MAC queue with a
  // frame in flight and crash (a segfault). The UAVs that fly keep their UEs in their BSS.
  GeneratorOptions options;
  options.seed = 91000;
  options.style = GeneratorStyle::kUrban;
  options.mobility = MobilityModel::kRandomWaypoint;
  Scenario s = GenerateScenario(options).scenario;
  s.env.decision_interval = 1.0;
  auto oracle = MakeTrackPositioner("oracle-track", s);
  const TrackResult r = RunTrack(s, *oracle, 5.0, TrackFidelity::kPacket);
  ASSERT_EQ(r.intervals.size(), 5u);
  for (const TrackInterval& i : r.intervals) {
    if (i.scored) {
      EXPECT_GT(i.throughput_mbps, 0.0) << i.time;
    }
  }
}

TEST(PacketTrack, RefusesARunThatEndsWithinTheWarmUp) {
  Scenario s = Walking(1, 1);
  s.simulation.warmup = 2.0;
  try {
    Track(s, 2.0, TrackFidelity::kPacket);
    ADD_FAILURE() << "a run with no interval after the warm-up was not refused";
  } catch (const ConfigError& e) {
    EXPECT_NE(e.describe().find("--duration: leaves no interval after simulation.warmup (2 s)"),
              std::string::npos)
        << e.describe();
  }
}

}  // namespace
}  // namespace rlpos
