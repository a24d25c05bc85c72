// Several UAVs moving at once: the joint move's conflict rule, each UAV's own observation, the
// global state and its bounds (worker/env/gym/multi_agent.h).
#include "worker/env/gym/multi_agent.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/scenario/building_obstacles.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/gym/moves.h"

namespace rlpos {
namespace {

// Three UAVs over a 150 m x 150 m grid of blocks up to 35 m tall; at z = 40 no building is in
// the way, so only the UAVs matter.
Scenario Urban3() {
  return ParseScenario(
      ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/urban3.json"));
}

bool Same(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

void ExpectPlacement(const Placement& got, const Placement& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t u = 0; u < want.size(); ++u) {
    EXPECT_TRUE(Same(got[u], want[u]))
        << "UAV " << u << " at (" << got[u].x << ", " << got[u].y << ", " << got[u].z << ")";
  }
}

TEST(JointMove, OneUavIsApplyDisplacement) {
  Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  s.uavs.resize(1);
  const Placement from{{50, 50, 40}};
  for (const Vec3& d : {Vec3{5, 0, 0}, Vec3{0, -200, 0}, Vec3{0, 0, 30}, Vec3{-2.5, 1, -1}})
    ExpectPlacement(ApplyJointDisplacement(s, buildings, {d}, from),
                    ApplyDisplacement(s, buildings, 0, d, from));
}

TEST(JointMove, AConvoyMovesTogether) {
  // UAV 0 flies into the spot UAV 1 leaves in the same step: at once, both move (taking turns,
  // UAV 0's move would be refused).
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const Placement from{{50, 50, 40}, {55, 50, 40}, {100, 100, 40}};
  const Placement to =
      ApplyJointDisplacement(s, buildings, {{5, 0, 0}, {5, 0, 0}, {0, 0, 0}}, from);
  ExpectPlacement(to, {{55, 50, 40}, {60, 50, 40}, {100, 100, 40}});
  ExpectPlacement(ApplyDisplacement(s, buildings, 0, {5, 0, 0}, from), from);
}

TEST(JointMove, TwoUavsAimingAtOneSpotTheLowerIndexWins) {
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const Placement from{{50, 50, 40}, {60, 50, 40}, {100, 100, 40}};
  ExpectPlacement(ApplyJointDisplacement(s, buildings, {{5, 0, 0}, {-5, 0, 0}, {0, 0, 0}}, from),
                  {{55, 50, 40}, {60, 50, 40}, {100, 100, 40}});
  // The same with the roles swapped: still UAV 0's move.
  const Placement mirrored{{60, 50, 40}, {50, 50, 40}, {100, 100, 40}};
  ExpectPlacement(
      ApplyJointDisplacement(s, buildings, {{-5, 0, 0}, {5, 0, 0}, {0, 0, 0}}, mirrored),
      {{55, 50, 40}, {50, 50, 40}, {100, 100, 40}});
}

TEST(JointMove, ARefusalThatBlocksAnotherRefusesItToo) {
  // UAV 1 loses to UAV 0 and stays; UAV 2 aimed next to where UAV 1 was leaving: it stays too.
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const Placement from{{50, 50, 40}, {58, 50, 40}, {58, 55, 40}};
  ExpectPlacement(
      ApplyJointDisplacement(s, buildings, {{5, 0, 0}, {-2.5, 0, 0}, {0, -4.5, 0}}, from),
      {{55, 50, 40}, {58, 50, 40}, {58, 55, 40}});
  // Without UAV 0 in the way, UAV 1 moves and UAV 2 with it.
  ExpectPlacement(
      ApplyJointDisplacement(s, buildings, {{0, 0, 0}, {-2.5, 0, 0}, {0, -4.5, 0}}, from),
      {{50, 50, 40}, {55.5, 50, 40}, {58, 50.5, 40}});
}

TEST(JointMove, AMoveOntoAStayingUavIsRefused) {
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const Placement from{{50, 50, 40}, {55, 50, 40}, {100, 100, 40}};
  ExpectPlacement(ApplyJointDisplacement(s, buildings, {{0, 0, 0}, {-5, 0, 0}, {0, 0, 0}}, from),
                  from);
}

TEST(JointMove, ZonesAndBuildingsFirstThenNoTwoUavsTooClose) {
  // Random placements and moves: every UAV ends at its move resolved alone or where it was, and
  // no two end closer than kMinUavSeparation.
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> coordinate(0, 20), move(-6, 6);
  int refused = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Placement from;
    while (from.size() < 3) {
      const Vec3 p{40 + coordinate(engine), 40 + coordinate(engine), 5 + coordinate(engine)};
      if (BuildingContaining(s, p) < 0 && !OverlapsAnother(from, from.size(), p))
        from.push_back(p);
    }
    std::vector<Vec3> d;
    for (int u = 0; u < 3; ++u)
      d.push_back({move(engine), move(engine), move(engine)});
    const Placement to = ApplyJointDisplacement(s, buildings, d, from);
    for (std::size_t u = 0; u < 3; ++u) {
      EXPECT_FALSE(OverlapsAnother(to, u, to[u])) << "trial " << trial;
      const Vec3 alone = TargetAlone(s, buildings, u, d[u], from[u]);
      EXPECT_TRUE(Same(to[u], alone) || Same(to[u], from[u])) << "trial " << trial;
      refused += !Same(alone, from[u]) && Same(to[u], from[u]);
    }
  }
  EXPECT_GT(refused, 0);  // the draws do make UAVs meet
}

TEST(JointMove, OneDisplacementPerUav) {
  const Scenario s = Urban3();
  const Obstacles buildings = BuildingObstacles(s.buildings);
  EXPECT_THROW(ApplyJointDisplacement(s, buildings, {{0, 0, 0}}, s.InitialPlacement()),
               std::invalid_argument);
}

StepInfo InfoAt(const Scenario& s) {
  StepInfo info;
  info.positions = s.InitialPlacement();
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    info.serving.push_back(static_cast<int>(i % s.uavs.size()));
    info.los.push_back(i % 2);
    info.snr_db.push_back(i == 0 ? 75.0 : -30.0 + static_cast<double>(i) * 4);
  }
  info.n_los = static_cast<int>(s.ues.size() / 2);
  info.throughput_mbps = 1e6;  // above the demand: clipped to it
  info.demands_met = 3;
  info.active_uav = 2;
  return info;
}

TEST(AgentObservation, EachUavSeesItselfAsTheActiveOne) {
  const Scenario s = Urban3();
  const StepInfo info = InfoAt(s);
  const BoxSpace bounds = ObservationBounds(s);
  for (std::size_t u = 0; u < 3; ++u) {
    const auto obs = AgentObservation(s, info, u);
    EXPECT_TRUE(bounds.Contains(obs));
    StepInfo as_active = info;
    as_active.active_uav = static_cast<int>(u);
    EXPECT_EQ(obs, MakeObservation(s, as_active));
    for (std::size_t v = 0; v < 3; ++v)  // the one-hot closes the observation
      EXPECT_EQ(obs[obs.size() - 3 + v], u == v ? 1.0 : 0.0);
  }
}

TEST(State, LayoutAndBounds) {
  const Scenario s = Urban3();
  const StepInfo info = InfoAt(s);
  const std::size_t n = s.ues.size();
  const BoxSpace bounds = StateBounds(s);
  const auto state = MakeState(s, info);
  ASSERT_EQ(state.size(), 3 * 3 + 3 * n + 2);
  ASSERT_EQ(bounds.Dim(), state.size());
  EXPECT_TRUE(bounds.Contains(state));
  for (std::size_t u = 0; u < 3; ++u) {
    EXPECT_EQ(state[3 * u], info.positions[u].x);
    EXPECT_EQ(state[3 * u + 1], info.positions[u].y);
    EXPECT_EQ(state[3 * u + 2], info.positions[u].z);
    EXPECT_EQ(bounds.low[3 * u + 2], s.uavs[u].zone.zmin);
    EXPECT_EQ(bounds.high[3 * u + 2], s.uavs[u].zone.zmax);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = 9 + 3 * i;
    EXPECT_EQ(state[at], info.los[i]);
    EXPECT_EQ(state[at + 1], std::clamp(info.snr_db[i], -20.0, 60.0));
    EXPECT_EQ(state[at + 2], info.serving[i]);
    EXPECT_EQ(bounds.high[at + 2], 2.0);
  }
  EXPECT_EQ(state[9 + 3 * n], s.TotalDemandMbps());
  EXPECT_EQ(state[10 + 3 * n], 3.0);
  StepInfo short_info = info;
  short_info.los.pop_back();  // a fidelity that did not fill a field is a bug, not a state
  EXPECT_THROW(MakeState(s, short_info), std::logic_error);
}

}  // namespace
}  // namespace rlpos
