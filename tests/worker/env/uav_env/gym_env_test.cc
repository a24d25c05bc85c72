// The UAV positioning env on scenario B, both fidelities.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/scenario/scenario_checks.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"

namespace rlpos {
namespace {

Scenario LoadB(std::vector<std::string> overrides) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json", overrides);
}

int Action(const Scenario& s, const std::string& name) {
  return static_cast<int>(std::find(s.env.actions.begin(), s.env.actions.end(), name) -
                          s.env.actions.begin());
}

TEST(GymEnv, AnalyticResetStepTruncate) {
  const Scenario s = LoadB({"env.fidelity=analytic", "env.episode_duration=1"});
  UavPositioningEnv env(s);
  EXPECT_EQ(env.ActionSpace().n, 7);
  EXPECT_EQ(env.StepsPerEpisode(), 10);
  const auto obs = env.Reset(1);
  EXPECT_EQ(obs, (std::vector<double>{50, 50, 25, 1}));  // x, y, z, nLoS at the baseline
  EXPECT_TRUE(env.ObservationSpace().Contains(obs));
  StepResult r;
  for (int i = 0; i < 3; ++i)
    r = env.Step(Action(s, "backward"));  // to (50, 35, 25): all LoS
  EXPECT_EQ(r.observation, (std::vector<double>{50, 35, 25, 4}));
  EXPECT_NEAR(r.reward, 1.0, 1e-3);  // 0.8 * 4/4 + 0.2 * 234/234
  EXPECT_FALSE(r.truncated);
  for (int i = 0; i < 7; ++i)
    r = env.Step(Action(s, "stay"));
  EXPECT_TRUE(r.truncated);
  EXPECT_FALSE(r.terminated);
  EXPECT_THROW(env.Step(7), std::out_of_range);
}

TEST(GymEnv, ContinuousActionsAreBoundedDisplacements) {
  const Scenario s = LoadB({"env.fidelity=analytic", "env.episode_duration=1",
                            "agent.algorithm=sac", "env.action_space=continuous"});
  UavPositioningEnv env(s);
  EXPECT_EQ(env.ActionSpace().n, 0);
  const BoxSpace box = env.ContinuousActionSpace();
  EXPECT_EQ(box.low, (std::vector<double>{-5, -5, -5}));
  EXPECT_EQ(box.high, (std::vector<double>{5, 5, 5}));
  EXPECT_TRUE(env.ValidActions().empty());  // no mask: the displacement is clamped
  env.Reset(1);
  StepResult r = env.StepContinuous({0, -5, 0});
  r = env.StepContinuous({0, -5, 0});
  r = env.StepContinuous({0.5, -5, -2.5});  // to (50.5, 35, 22.5): all LoS
  EXPECT_EQ(r.info.positions[0].x, 50.5);
  EXPECT_EQ(r.info.positions[0].y, 35.0);
  EXPECT_EQ(r.info.positions[0].z, 22.5);
  EXPECT_EQ(r.info.n_los, 4);
  EXPECT_THROW(env.StepContinuous({5.5, 0, 0}), std::out_of_range);
  EXPECT_THROW(env.StepContinuous({0, 0}), std::out_of_range);
  EXPECT_THROW(env.StepContinuous({std::nan(""), 0, 0}), std::out_of_range);
  EXPECT_THROW(env.Step(0), std::out_of_range);
  EXPECT_EQ(env.LastInfo().positions[0].x, 50.5);  // a refused action moves nothing

  UavPositioningEnv discrete(LoadB({"env.fidelity=analytic"}));
  discrete.Reset(1);
  EXPECT_THROW(discrete.StepContinuous({0, 0, 0}), std::out_of_range);
}

std::vector<std::string> Masked(const Scenario& s, const ActionMask& mask) {
  std::vector<std::string> out;
  for (std::size_t a = 0; a < mask.size(); ++a) {
    if (!mask[a])
      out.push_back(s.env.actions[a]);
  }
  return out;
}

TEST(GymEnv, MovesIntoWallsAndBuildingsAreMaskedStayIsNot) {
  using Names = std::vector<std::string>;
  // The baseline (50, 50, 25) is 5 m above the tower: "down" would end on its roof.
  const Scenario above_tower = LoadB({"env.fidelity=analytic"});
  UavPositioningEnv env(above_tower);
  env.Reset(1);
  EXPECT_EQ(Masked(above_tower, env.ValidActions()), Names{"down"});
  const Scenario ceiling = LoadB({"env.fidelity=analytic", "uav.position=[20,20,60]"});
  UavPositioningEnv at_ceiling(ceiling);
  at_ceiling.Reset(1);
  EXPECT_EQ(Masked(ceiling, at_ceiling.ValidActions()), Names{"up"});
  at_ceiling.Step(Action(ceiling, "down"));  // away from the wall: nothing masked
  EXPECT_TRUE(Masked(ceiling, at_ceiling.ValidActions()).empty());
  const Scenario corner = LoadB({"env.fidelity=analytic", "uav.position=[0,0,5]"});
  UavPositioningEnv at_corner(corner);
  at_corner.Reset(1);
  EXPECT_EQ(Masked(corner, at_corner.ValidActions()), (Names{"down", "backward", "left"}));
  // Without the mask the walls only clamp: every action stays allowed.
  const Scenario unmasked =
      LoadB({"env.fidelity=analytic", "uav.position=[0,0,5]", "env.action_mask=false"});
  UavPositioningEnv clamped(unmasked);
  clamped.Reset(1);
  EXPECT_TRUE(clamped.ValidActions().empty());
}

bool OnLattice(double v, double from, double step) {
  const double k = (v - from) / step;
  return std::abs(k - std::round(k)) < 1e-9;
}

TEST(GymEnv, ExploringStartsDrawLatticePointsOfTheZoneOutsideBuildings) {
  const Scenario s = LoadB({"env.fidelity=analytic"});
  UavPositioningEnv env(s);
  const Vec3 baseline = s.InitialPlacement()[0];
  const Box& zone = s.uavs[0].zone;
  std::set<std::vector<double>> starts;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const std::vector<double> obs = env.Reset(seed, ResetOptions{true});
    const Vec3 p = env.LastInfo().positions[0];
    EXPECT_EQ(obs[0], p.x);
    EXPECT_TRUE(OnLattice(p.x, baseline.x, s.env.step) && OnLattice(p.y, baseline.y, s.env.step) &&
                OnLattice(p.z, baseline.z, s.env.step))
        << "seed " << seed;
    EXPECT_TRUE(p.x >= zone.xmin && p.x <= zone.xmax && p.y >= zone.ymin && p.y <= zone.ymax &&
                p.z >= zone.zmin && p.z <= zone.zmax)
        << "seed " << seed;
    EXPECT_LT(BuildingContaining(s, p), 0) << "seed " << seed;
    EXPECT_EQ(env.Reset(seed, ResetOptions{true}), obs) << "seed " << seed;  // seeded
    starts.insert(obs);
  }
  // B's lattice has 21 x 21 x 12 points; 300 draws land on many of them, all over the zone.
  EXPECT_GT(starts.size(), 250u);
  EXPECT_EQ(env.Reset(7), (std::vector<double>{50, 50, 25, 1}));  // no option: the baseline
}

TEST(GymEnv, ExploringStartsKeepSeveralUavsApart) {
  const Scenario s =
      LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json",
                   {"env.fidelity=analytic"});
  UavPositioningEnv env(s);
  const Placement baseline = s.InitialPlacement();
  const auto same = [](const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  int moved = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    env.Reset(seed, ResetOptions{true});
    const Placement& p = env.LastInfo().positions;
    ASSERT_EQ(p.size(), 2u);
    EXPECT_FALSE(OverlapsAnother(p, 0, p[0])) << "seed " << seed;
    moved += !same(p[0], baseline[0]) && !same(p[1], baseline[1]);
  }
  EXPECT_GT(moved, 90);  // both UAVs start away from their baselines
}

TEST(GymEnv, PacketStepsAdvanceNs3AndMeasureTheInterval) {
  const Scenario s = LoadB({"env.fidelity=packet", "env.episode_duration=0.5",
                            "env.decision_interval=0.25", "simulation.warmup=0.5"});
  UavPositioningEnv env(s);
  env.Reset(1001);
  StepResult r;
  for (int i = 0; i < 2; ++i)
    r = env.Step(Action(s, "stay"));
  EXPECT_TRUE(r.truncated);
  EXPECT_EQ(r.info.n_los, 1);
  // At the baseline the two weak NLoS UEs and the LoS one deliver most of their demand.
  EXPECT_GT(r.info.throughput_mbps, 100.0);
  EXPECT_LT(r.info.throughput_mbps, 240.0);
  EXPECT_GT(env.WallSecondsInNs3(), 0.0);
}

TEST(GymEnv, AnalyticAgreesWithPacketAtAnAllLosPosition) {
  Scenario s = LoadB({"env.episode_duration=0.5", "env.decision_interval=0.5",
                      "simulation.warmup=1", "uav.position=[50, 35, 10]"});
  s.env.fidelity = "packet";
  UavPositioningEnv packet(s);
  packet.Reset(1001);
  const double measured = packet.Step(Action(s, "stay")).info.throughput_mbps;
  s.env.fidelity = "analytic";
  UavPositioningEnv analytic(s);
  analytic.Reset(1);
  const double estimated = analytic.Step(Action(s, "stay")).info.throughput_mbps;
  EXPECT_NEAR(estimated, measured, 0.1 * measured);
}

}  // namespace
}  // namespace rlpos
