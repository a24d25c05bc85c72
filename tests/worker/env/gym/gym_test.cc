// Spaces, moves and clamping, observations, rewards: the gym's pure parts.
#include <gtest/gtest.h>

#include <cmath>

#include "common/scenario/building_obstacles.h"
#include "common/scenario/names.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/gym/lattice_route.h"
#include "worker/env/gym/moves.h"
#include "worker/env/gym/reward.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {
namespace {

Scenario ScenarioB() {
  return ParseScenario(ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json"));
}

int ActionIndex(const Scenario& s, const std::string& name) {
  for (std::size_t i = 0; i < s.env.actions.size(); ++i) {
    if (s.env.actions[i] == name)
      return static_cast<int>(i);
  }
  return -1;
}

TEST(Spaces, DiscreteAndBox) {
  const DiscreteSpace d{7};
  EXPECT_TRUE(d.Contains(0));
  EXPECT_TRUE(d.Contains(6));
  EXPECT_FALSE(d.Contains(7));
  EXPECT_FALSE(d.Contains(-1));
  const BoxSpace box{{0, -10}, {100, 10}};
  EXPECT_TRUE(box.Contains({50, 0}));
  EXPECT_FALSE(box.Contains({50, 11}));
  EXPECT_FALSE(box.Contains({50}));
  const auto n = box.Normalise({0, 10});
  EXPECT_FLOAT_EQ(n[0], -1.0f);
  EXPECT_FLOAT_EQ(n[1], 1.0f);
}

// The observation as the Python env gives it (and a policy exported from Python is fed):
// float32, clipped to the float32 bounds, NaN kept, not normalised.
TEST(Spaces, Float32ClipGivesThePythonEnvsObservation) {
  const Float32Clip clip(BoxSpace{{0.0, -0.1}, {100.0, 0.1}});
  const auto o = clip({50.25, 7.0});
  EXPECT_EQ(o[0], 50.25f);
  EXPECT_EQ(o[1], 0.1f);  // the bound, in float32
  EXPECT_EQ(clip({-1.0, 2.0})[0], 0.0f);
  EXPECT_TRUE(std::isnan(clip({std::nan(""), 5.0})[0]));
}

// One UAV's move.
Vec3 Move(const Scenario& s, int action, const Vec3& from) {
  return ApplyMove(s, BuildingObstacles(s.buildings), 0, action, {from})[0];
}

TEST(Moves, EachActionMovesOneStepInItsDirection) {
  const Scenario s = ScenarioB();  // step 5 m, baseline (50, 50, 25)
  const Vec3 p{50, 35, 30};
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "up"), p).z, 35);
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "down"), p).z, 25);
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "forward"), p).y, 40);
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "backward"), p).y, 30);
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "right"), p).x, 55);
  EXPECT_DOUBLE_EQ(Move(s, ActionIndex(s, "left"), p).x, 45);
  const Vec3 stay = Move(s, ActionIndex(s, "stay"), p);
  EXPECT_DOUBLE_EQ(stay.x, p.x);
  EXPECT_DOUBLE_EQ(stay.y, p.y);
  EXPECT_DOUBLE_EQ(stay.z, p.z);
}

TEST(Moves, ZoneClampsAndAWallIsNotALoop) {
  const Scenario s = ScenarioB();  // zone z in [5, 60]
  Vec3 p{50, 35, 58};
  p = Move(s, ActionIndex(s, "up"), p);
  EXPECT_DOUBLE_EQ(p.z, 60);  // clamped, not 63
  p = Move(s, ActionIndex(s, "up"), p);
  EXPECT_DOUBLE_EQ(p.z, 60);  // stays at the wall
  Vec3 corner{0, 0, 5};
  corner = Move(s, ActionIndex(s, "left"), corner);
  corner = Move(s, ActionIndex(s, "backward"), corner);
  corner = Move(s, ActionIndex(s, "down"), corner);
  EXPECT_DOUBLE_EQ(corner.x, 0);
  EXPECT_DOUBLE_EQ(corner.y, 0);
  EXPECT_DOUBLE_EQ(corner.z, 5);
}

TEST(Moves, NeverIntoABuilding) {
  const Scenario s = ScenarioB();  // tower [45, 55]^2, 20 m
  const Vec3 above{50, 50, 25};
  const Vec3 p = Move(s, ActionIndex(s, "down"), above);  // to z = 20: the roof
  EXPECT_DOUBLE_EQ(p.z, 25);
}

// "to_best": one move along the axis of the largest remaining offset, landing on the target,
// the next axis when that one is blocked, nothing at the target.
TEST(Moves, ToBestStepsAlongTheLargestOffsetAndAroundABlockedAxis) {
  const Scenario s = ScenarioB();  // step 5 m; tower [45, 55]^2, 20 m; zone z in [5, 60]
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const auto towards = [&](const Vec3& from, const Vec3& target) {
    return StepTowards(s, buildings, 0, target, {from});
  };
  const Vec3 p{30, 30, 30};
  const Vec3 a = towards(p, {42, 27, 30});  // x by 12, y by -3
  EXPECT_DOUBLE_EQ(a.x, 5);
  EXPECT_DOUBLE_EQ(a.y, 0);
  EXPECT_DOUBLE_EQ(a.z, 0);
  const Vec3 b = towards(p, {32, 27, 30});  // y is the larger: lands on it
  EXPECT_DOUBLE_EQ(b.x, 0);
  EXPECT_DOUBLE_EQ(b.y, -3);
  const Vec3 tie = towards(p, {25, 30, 35});  // x on a tie
  EXPECT_DOUBLE_EQ(tie.x, -5);
  EXPECT_DOUBLE_EQ(tie.z, 0);
  const Vec3 here = towards(p, p);
  EXPECT_EQ(here.x == 0 && here.y == 0 && here.z == 0, true);
  // Beside the tower at 15 m: x leads into it, so y it is.
  const Vec3 c = towards({40, 50, 15}, {60, 52, 15});
  EXPECT_DOUBLE_EQ(c.x, 0);
  EXPECT_DOUBLE_EQ(c.y, 2);
  // At the zone's ceiling a target above cannot be neared: nothing moves.
  const Vec3 d = towards({30, 30, 60}, {30, 30, 70});
  EXPECT_EQ(d.x == 0 && d.y == 0 && d.z == 0, true);
  // A scenario without the move has no index for it.
  EXPECT_EQ(ToBestAction(s), -1);
  Scenario with = s;
  with.env.actions.push_back("to_best");
  EXPECT_EQ(ToBestAction(with), 7);
}

// The way round: behind B's tower (x, y in [45, 55], 20 m) the straight move is stuck; the route
// takes a shortest way round (8 moves: two aside, four across, two back) and lands on the target.
TEST(LatticeRoute, GoesRoundABuildingTheStraightMoveIsStuckBehind) {
  const Scenario s = ScenarioB();  // lattice through (50, 50, 25) by 5 m, zone z in [5, 60]
  const Vec3 start{40, 50, 15}, target{60, 50, 15};
  const Obstacles buildings = BuildingObstacles(s.buildings);
  const Vec3 straight = StepTowards(s, buildings, 0, target, {start});
  EXPECT_TRUE(straight.x == 0 && straight.y == 0 && straight.z == 0);
  LatticeRoute route(s, buildings, 0);
  Placement at{start};
  int moves = 0;
  for (; moves < 40; ++moves) {
    const Vec3 move = route.NextMove(target, at);
    if (move.x == 0 && move.y == 0 && move.z == 0)
      break;
    at = ApplyDisplacement(s, buildings, 0, move, at);
    ASSERT_LT(BuildingContaining(s, at[0]), 0) << "move " << moves;
  }
  EXPECT_EQ(moves, 8);
  EXPECT_EQ(at[0].x, target.x);
  EXPECT_EQ(at[0].y, target.y);
  EXPECT_EQ(at[0].z, target.z);
  // Off the lattice, or towards a point inside the tower, it is the straight move.
  const Vec3 off{42, 50, 30};
  const Vec3 a = route.NextMove({60, 50, 30}, {off}),
             b = StepTowards(s, buildings, 0, {60, 50, 30}, {off});
  EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z);
  const Vec3 c = route.NextMove({50, 50, 10}, {Vec3{30, 50, 10}});
  EXPECT_DOUBLE_EQ(c.x, 5);
  // A lattice too fine to search (0.25 m over B's zone: 401 x 401 x 221 points) keeps the
  // straight move, here stuck behind the tower, without building it.
  Scenario fine = s;
  fine.env.step = 0.25;
  LatticeRoute coarse_only(fine, buildings, 0);
  const Vec3 stuck = coarse_only.NextMove(target, {Vec3{44.75, 50, 15}});
  EXPECT_TRUE(stuck.x == 0 && stuck.y == 0 && stuck.z == 0);
}

TEST(Observations, LayoutAndBounds) {
  Scenario s = ScenarioB();
  s.env.observations = {"x", "y", "z", "n_los", "throughput", "snr"};
  const BoxSpace box = ObservationBounds(s);
  ASSERT_EQ(box.Dim(), 5u + s.ues.size());
  StepInfo info;
  info.positions = {{10, 20, 30}};
  info.n_los = 3;
  info.throughput_mbps = 100;
  info.snr_db = {10, 80, -40, 0};  // out-of-range SNRs are clipped into the space
  const auto obs = MakeObservation(s, info);
  EXPECT_EQ(obs.size(), box.Dim());
  EXPECT_TRUE(box.Contains(obs));
  EXPECT_DOUBLE_EQ(obs[0], 10);
  EXPECT_DOUBLE_EQ(obs[3], 3);
  EXPECT_DOUBLE_EQ(obs[4], 100);
  EXPECT_DOUBLE_EQ(obs[6], 60);
}

TEST(Reward, PaperArithmetic) {
  const auto r = MakeReward({"paper", 0.8, 0.2, 0.0});
  // 3 of 4 LoS, 117 of 234 Mbit/s: 0.8 * 0.75 + 0.2 * 0.5
  EXPECT_DOUBLE_EQ((*r)({3, 4, 117.0, 234.0, 0}), 0.7);
  EXPECT_DOUBLE_EQ((*r)({4, 4, 234.0, 234.0, 4}), 1.0);
  const auto weights = MakeReward({"paper", 0.5, 0.5, 0.0});
  EXPECT_DOUBLE_EQ((*weights)({1, 4, 0.0, 234.0, 0}), 0.125);
}

TEST(Reward, DemandAwareAddsDemandsMet) {
  const auto r = MakeReward({"demand_aware", 0.8, 0.2, 0.2});
  EXPECT_DOUBLE_EQ((*r)({3, 4, 117.0, 234.0, 2}), 0.7 + 0.2 * 0.5);
}

// The parser's names (kRewards) are the rewards there are: each makes one, and no other does.
TEST(Reward, EveryDeclaredNameMakesARewardAndNoOther) {
  for (const std::string_view name : kRewards)
    EXPECT_NE(MakeReward({std::string(name), 0.8, 0.2, 0.2}), nullptr) << name;
  EXPECT_THROW(MakeReward({"nope", 0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(MakeReward({"", 0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
