// A run in which the UEs move and the UAVs follow: scored as the analytic model scores a
// placement, within the speed limits, the same numbers for the same RngRun.
#include "worker/positioning/track/track_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/config/config_error.h"
#include "tests/worker/positioning/track/track_test_support.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/positioners.h"

namespace rlpos {
namespace {

using testing::Shipped;
using testing::Walking;

TrackResult Track(const Scenario& s, const std::string& positioner, double duration) {
  auto p = MakeTrackPositioner(positioner, s);
  return RunTrack(s, *p, duration);
}

TEST(TrackRun, StaticUesScoreEveryIntervalAsThePlacementIsScored) {
  const Scenario b = Shipped("b", {"env.decision_interval=0.5"});
  const std::pair<const char*, Placement> held[] = {{"baseline", BaselinePlacement(b)},
                                                    {"centroid", CentroidPlacement(b)}};
  for (const auto& [name, placement] : held) {
    const double expected = AnalyticReward(b, placement);
    const TrackResult r = Track(b, name, 5.0);
    ASSERT_EQ(r.intervals.size(), 10u) << name;
    for (const TrackInterval& i : r.intervals)
      EXPECT_EQ(i.reward, expected) << name << " at " << i.time;
    EXPECT_EQ(r.metrics.mean_reward, expected) << name;
    EXPECT_EQ(r.metrics.distance_flown_m, 0.0) << name;
  }
  // The UEs stay: so does the tracking oracle, at the held oracle's placement.
  const TrackResult held_oracle = Track(b, "oracle", 2.0);
  const TrackResult tracking = Track(b, "oracle-track", 2.0);
  for (const TrackInterval& i : tracking.intervals)
    EXPECT_EQ(i.reward, held_oracle.intervals.front().reward) << i.time;
  EXPECT_EQ(tracking.metrics.distance_flown_m, 0.0);
}

TEST(TrackRun, NoUavFliesFasterThanItsLimits) {
  // Two UAVs of which the first is slow; the oracle with one (two would take a minute).
  for (const auto& [positioner, uavs] : {std::pair{"centroid-track", 2}, {"oracle-track", 1}}) {
    Scenario s = Walking(uavs, 1);
    s.uavs[0].max_speed = 1.5;
    s.uavs[0].max_climb = 0.5;
    const TrackResult r = Track(s, positioner, 60.0);
    Placement before = r.intervals.front().targets;  // deployed at the decision for t = 0
    double flown = 0.0, fastest = 0.0;
    for (const TrackInterval& i : r.intervals) {
      for (std::size_t u = 0; u < s.uavs.size(); ++u) {
        const Vec3& a = before[u];
        const Vec3& b = i.positions[u];
        const double horizontal = std::hypot(b.x - a.x, b.y - a.y);
        EXPECT_LE(horizontal, s.uavs[u].max_speed * 1.0 + 1e-9) << positioner << " " << i.time;
        EXPECT_LE(std::abs(b.z - a.z), s.uavs[u].max_climb * 1.0 + 1e-9)
            << positioner << " " << i.time;
        flown += std::hypot(horizontal, b.z - a.z);
        if (u == 0)
          fastest = std::max(fastest, horizontal);
      }
      before = i.positions;
    }
    EXPECT_NEAR(r.metrics.distance_flown_m, flown, 1e-6) << positioner;
    EXPECT_GT(r.metrics.distance_flown_m, 0.0) << positioner << ": the UAVs never followed";
    EXPECT_NEAR(fastest, 1.5, 1e-9) << positioner << ": the slow UAV's limit never bound";
  }
}

TEST(TrackRun, UesThatWalkFromOneUavToAnotherAreHandedOver) {
  const Scenario s = Walking(2, 1);
  const TrackResult r = Track(s, "centroid-track", 60.0);
  std::size_t changes = 0;
  for (std::size_t i = 1; i < r.intervals.size(); ++i) {
    for (std::size_t ue = 0; ue < s.ues.size(); ++ue)
      changes += r.intervals[i].serving[ue] != r.intervals[i - 1].serving[ue] ? 1 : 0;
  }
  EXPECT_GT(changes, 0u) << "no UE walked from one UAV to the other: pick another walk";
  EXPECT_EQ(r.metrics.handovers, static_cast<double>(changes));
  EXPECT_EQ(Track(Walking(1, 1), "centroid-track", 60.0).metrics.handovers, 0.0);
}

TEST(TrackRun, P5OverTimeIsTheFifthPercentileOfTheIntervals) {
  const TrackResult r = Track(Walking(1, 2), "centroid-track", 41.0);  // 41 intervals
  std::vector<double> rewards, throughputs;
  for (const TrackInterval& i : r.intervals) {
    rewards.push_back(i.reward);
    throughputs.push_back(i.throughput_mbps);
  }
  // Type 7 over 41 values: (41 - 1) * 0.05 = 2, the third smallest exactly.
  std::sort(rewards.begin(), rewards.end());
  std::sort(throughputs.begin(), throughputs.end());
  EXPECT_EQ(r.metrics.reward_p5, rewards[2]);
  EXPECT_EQ(r.metrics.throughput_p5_mbps, throughputs[2]);
  EXPECT_LT(r.metrics.reward_p5, rewards.back()) << "a walk whose reward never changes";
  EXPECT_LE(r.metrics.demands_met_share_p5, 1.0 - r.metrics.outage_share);
  EXPECT_LE(r.metrics.los_share_p5, r.metrics.los_share);
}

TEST(TrackRun, TheSameRngRunGivesTheSameNumbers) {
  const auto series = [](const TrackResult& r) {
    std::vector<double> values;
    for (const TrackInterval& i : r.intervals) {
      values.push_back(i.reward);
      values.push_back(i.throughput_mbps);
      for (const Vec3& p : i.positions)
        values.insert(values.end(), {p.x, p.y, p.z});
    }
    return values;
  };
  const TrackResult first = Track(Walking(1, 3), "oracle-track", 20.0);
  const TrackResult again = Track(Walking(1, 3), "oracle-track", 20.0);
  const TrackResult other = Track(Walking(1, 4), "oracle-track", 20.0);
  EXPECT_EQ(series(first), series(again));
  EXPECT_EQ(first.metrics.mean_reward, again.metrics.mean_reward);
  EXPECT_NE(series(first), series(other)) << "another RngRun, the same walk";
}

// `run` throws a ConfigError whose "path: problem" holds `fragment`.
template <typename F>
void ExpectRefused(F run, const std::string& fragment) {
  try {
    run();
    ADD_FAILURE() << "not refused: " << fragment;
  } catch (const ConfigError& e) {
    EXPECT_NE(e.describe().find(fragment), std::string::npos) << e.describe();
  }
}

TEST(TrackRun, RefusesWhatItCannotRun) {
  const Scenario b = Shipped("b");
  ExpectRefused([&] { Track(b, "oracle", -1.0); },
                "--duration: must be at least env.decision_interval (0.1 s), got -1");
  ExpectRefused([&] { Track(b, "oracle", 0.05); }, "--duration: must be at least");
  ExpectRefused([&] { MakeTrackPositioner("rl", b); },
                "--positioner: rl flies a policy, which the RL module loads");
  ExpectRefused([&] { MakeTrackPositioner("offsets", b); }, "--positioner: offsets are placed");
  ExpectRefused([&] { MakeTrackPositioner("teleport", b); },
                "--positioner: unknown positioner \"teleport\"");
}

}  // namespace
}  // namespace rlpos
