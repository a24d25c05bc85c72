// The evaluator told where the UEs are gives what a scenario with its UEs there gives; the
// tracking oracle's reused links give every decision exactly the oracle searched afresh.
#include "worker/positioning/positioners/tracking_oracle.h"

#include <gtest/gtest.h>

#include "common/mobility/ue_trajectories.h"
#include "tests/worker/positioning/track/track_test_support.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/positioners.h"

namespace rlpos {
namespace {

using testing::Shipped;
using testing::Walking;

Scenario Moved(Scenario s, const std::vector<Vec3>& ues) {
  for (std::size_t i = 0; i < ues.size(); ++i)
    s.ues[i].position = ues[i];
  return s;
}

double Reward(const Scenario& s, const Placement& p) {
  return AnalyticReward(s, p);
}

TEST(AnalyticEvaluatorUes, TheUesWhereTheyAreAsIfTheScenarioPutThemThere) {
  const Scenario b = Shipped("b");
  std::vector<Vec3> ues;
  for (const UeSpec& ue : b.ues)
    ues.push_back({ue.position.x + 7, ue.position.y - 3, ue.position.z});
  AnalyticEvaluator moved(b);
  const Placement p{{50, 30, 20}};
  const StepInfo before = moved.Evaluate(p);  // memorised at the old UE positions
  moved.SetUePositions(ues);
  AnalyticEvaluator fresh(Moved(b, ues));
  const StepInfo after = moved.Evaluate(p);
  const StepInfo expected = fresh.Evaluate(p);
  EXPECT_EQ(after.n_los, expected.n_los);
  EXPECT_EQ(after.throughput_mbps, expected.throughput_mbps);
  EXPECT_EQ(after.snr_db, expected.snr_db);
  EXPECT_NE(after.snr_db, before.snr_db) << "the UEs' move changed nothing";
  EXPECT_THROW(moved.SetUePositions({{1, 1, 1}}), std::invalid_argument);
}

// Each decision against OracleSearch (no packet re-score) of the scenario with the UEs there.
void ExpectFreshOracleEveryDecision(const Scenario& s, bool same_placement) {
  const auto trajectories = UeTrajectories(s);
  TrackingOracle oracle(s);
  OracleOptions options;
  options.packet_candidates = 0;
  for (double t : {0.0, 30.0, 30.0}) {  // again at 30 s: no UE moved since
    std::vector<Vec3> ues;
    for (const auto& trajectory : trajectories)
      ues.push_back(trajectory.PositionAt(t));
    const Scenario there = Moved(s, ues);
    const Placement decided = oracle.Decide(ues);
    const Placement fresh = OracleSearch(there, options).front().placement;
    if (same_placement || t == 0.0) {
      ASSERT_EQ(decided.size(), fresh.size());
      for (std::size_t u = 0; u < fresh.size(); ++u) {
        EXPECT_EQ(decided[u].x, fresh[u].x) << "t " << t << " UAV " << u;
        EXPECT_EQ(decided[u].y, fresh[u].y) << "t " << t << " UAV " << u;
        EXPECT_EQ(decided[u].z, fresh[u].z) << "t " << t << " UAV " << u;
      }
    } else {
      // The previous decision is one more start: at least as good.
      EXPECT_GE(Reward(there, decided), Reward(there, fresh) - 1e-12) << "t " << t;
    }
  }
}

TEST(TrackingOracle, OneUavDecidesTheGridOptimumForTheUesNow) {
  ExpectFreshOracleEveryDecision(Walking(1), true);
}

TEST(TrackingOracle, OneUavBeyondTheLinkBudgetDecidesTheSame) {
  const Scenario s = Walking(1);
  TrackingOracle tabulated(s);
  TrackingOracle untabulated(s, 0);
  const auto trajectories = UeTrajectories(s);
  for (double t : {0.0, 30.0}) {
    std::vector<Vec3> ues;
    for (const auto& trajectory : trajectories)
      ues.push_back(trajectory.PositionAt(t));
    const Placement a = tabulated.Decide(ues);
    const Placement b = untabulated.Decide(ues);
    EXPECT_EQ(a[0].x, b[0].x);
    EXPECT_EQ(a[0].y, b[0].y);
    EXPECT_EQ(a[0].z, b[0].z);
  }
}

TEST(TrackingOracle, SeveralUavsAtLeastAsGoodAsTheOracleSearchedAfresh) {
  ExpectFreshOracleEveryDecision(Walking(2), false);
}

}  // namespace
}  // namespace rlpos
