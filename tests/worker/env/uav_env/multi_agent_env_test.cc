// UavPositioningEnv::JointStep: every UAV moves at once, one decision interval, an observation per
// UAV, one team reward and the global state.
#include <gtest/gtest.h>

#include <random>

#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"

namespace rlpos {
namespace {

Scenario Load(const std::string& name, std::vector<std::string> overrides) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json",
                      overrides);
}

int MoveIndex(const Scenario& s, const std::string& name) {
  return static_cast<int>(std::find(s.env.actions.begin(), s.env.actions.end(), name) -
                          s.env.actions.begin());
}

void ExpectSamePositions(const Placement& a, const Placement& b, int step) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t u = 0; u < a.size(); ++u) {
    EXPECT_EQ(a[u].x, b[u].x) << "step " << step;
    EXPECT_EQ(a[u].y, b[u].y) << "step " << step;
    EXPECT_EQ(a[u].z, b[u].z) << "step " << step;
  }
}

TEST(JointStep, OneUavGivesStepsTrajectory) {
  const Scenario s = Load("b", {"env.fidelity=analytic", "env.episode_duration=5"});
  UavPositioningEnv single(s), team(s);
  const auto first = single.Reset(3, ResetOptions{true});
  EXPECT_EQ(team.Reset(3, ResetOptions{true}), first);
  EXPECT_EQ(team.AgentObservations(), std::vector<std::vector<double>>{first});
  std::mt19937_64 engine(5);
  std::uniform_int_distribution<int> action(0, single.ActionSpace().n - 1);
  for (int i = 0; i < single.StepsPerEpisode(); ++i) {
    const int a = action(engine);
    const StepResult r = single.Step(a);
    const JointStepResult m = team.JointStep({a});
    ASSERT_EQ(m.observations.size(), 1u);
    EXPECT_EQ(m.observations[0], r.observation) << "step " << i;
    EXPECT_EQ(m.reward, r.reward) << "step " << i;
    EXPECT_EQ(m.truncated, r.truncated) << "step " << i;
    EXPECT_EQ(m.terminated, r.terminated) << "step " << i;
    ExpectSamePositions(m.info.positions, r.info.positions, i);
    EXPECT_EQ(m.info.snr_db, r.info.snr_db) << "step " << i;
  }
  EXPECT_TRUE(team.LastInfo().positions.size() == 1 && team.StepsPerEpisode() == 50);
}

// What each UAV sees and the state, against the env's own LastInfo.
void ExpectConsistent(const UavPositioningEnv& env, const JointStepResult& m) {
  const Scenario& s = env.scenario();
  const StepInfo& info = env.LastInfo();
  const std::size_t k = s.uavs.size();
  const std::size_t n = s.ues.size();
  ASSERT_EQ(m.observations.size(), k);
  for (std::size_t u = 0; u < k; ++u) {
    const auto& obs = m.observations[u];
    EXPECT_TRUE(env.ObservationSpace().Contains(obs)) << "UAV " << u;
    // x of every UAV, then y, then z (env.observations), then nLoS, the SNRs, the one-hot.
    for (std::size_t v = 0; v < k; ++v) {
      EXPECT_EQ(obs[v], info.positions[v].x);
      EXPECT_EQ(obs[k + v], info.positions[v].y);
      EXPECT_EQ(obs[2 * k + v], info.positions[v].z);
      EXPECT_EQ(obs[obs.size() - k + v], u == v ? 1.0 : 0.0);
    }
    EXPECT_EQ(obs[3 * k], info.n_los);
    for (std::size_t u2 = 0; u2 < k; ++u2) {  // every UAV sees the same world
      if (u2 != u) {
        EXPECT_TRUE(
            std::equal(obs.begin(), obs.end() - static_cast<long>(k), m.observations[u2].begin()));
      }
    }
  }
  EXPECT_EQ(m.reward, env.RewardOf(info));
  ASSERT_EQ(m.state.size(), 3 * k + 3 * n + 2);
  EXPECT_TRUE(env.StateSpace().Contains(m.state));
  EXPECT_EQ(m.state, env.State());
  int los = 0;
  for (std::size_t u = 0; u < k; ++u) {
    EXPECT_EQ(m.state[3 * u], info.positions[u].x);
    EXPECT_EQ(m.state[3 * u + 1], info.positions[u].y);
    EXPECT_EQ(m.state[3 * u + 2], info.positions[u].z);
  }
  for (std::size_t i = 0; i < n; ++i) {
    los += static_cast<int>(m.state[3 * k + 3 * i]);
    EXPECT_EQ(m.state[3 * k + 3 * i + 2], info.serving[i]);
  }
  EXPECT_EQ(los, info.n_los);
  EXPECT_EQ(m.state.back(), info.demands_met);
}

TEST(JointStep, ThreeUavsMoveAtOnceAndSeeTheSameWorld) {
  const Scenario s = Load("urban3", {"env.fidelity=analytic", "env.episode_duration=2"});
  UavPositioningEnv env(s);
  env.Reset(1);
  const Placement start = env.LastInfo().positions;
  const int forward = MoveIndex(s, "forward");
  const JointStepResult m = env.JointStep({forward, forward, forward});
  ExpectConsistent(env, m);
  for (std::size_t u = 0; u < 3; ++u) {  // all three moved in one step
    EXPECT_EQ(m.info.positions[u].y, start[u].y + s.env.step) << "UAV " << u;
    EXPECT_EQ(m.info.positions[u].x, start[u].x) << "UAV " << u;
  }
  std::mt19937_64 engine(11);
  std::uniform_int_distribution<int> action(0, env.ActionSpace().n - 1);
  JointStepResult last = m;
  int steps = 1;
  while (!last.truncated) {
    last = env.JointStep({action(engine), action(engine), action(engine)});
    ExpectConsistent(env, last);
    ++steps;
  }
  EXPECT_EQ(steps, env.StepsPerEpisode());
  EXPECT_GT(last.info.n_los, 0);
}

TEST(JointStep, ContinuousDisplacementsPerUav) {
  const Scenario s = Load("urban3", {"env.fidelity=analytic", "env.episode_duration=1",
                                     "agent.algorithm=sac", "env.action_space=continuous"});
  UavPositioningEnv env(s);
  env.Reset(1);
  const Placement start = env.LastInfo().positions;
  const JointStepResult m = env.JointStepContinuous({{1, 0, 0}, {0, -2.5, 0}, {0, 0, 5}});
  ExpectConsistent(env, m);
  EXPECT_EQ(m.info.positions[0].x, start[0].x + 1);
  EXPECT_EQ(m.info.positions[1].y, start[1].y - 2.5);
  EXPECT_EQ(m.info.positions[2].z, start[2].z + 5);
  try {
    env.JointStepContinuous({{0, 0, 0}, {0, 0, 5.5}, {0, 0, 0}});
    FAIL() << "a component beyond env.step was taken";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("UAV 1 (\"uav2\")"), std::string::npos) << e.what();
  }
  EXPECT_THROW(env.JointStepContinuous({{0, 0, 0}, {0, 0}, {0, 0, 0}}), std::out_of_range);
  EXPECT_THROW(env.JointStep({0, 0, 0}), std::out_of_range);
}

TEST(JointStep, BadActionsAreRefusedAndMoveNothing) {
  const Scenario s = Load("urban3", {"env.fidelity=analytic", "env.episode_duration=1"});
  UavPositioningEnv env(s);
  EXPECT_THROW(env.JointStep({0, 0, 0}), std::logic_error);  // before the first Reset
  env.Reset(1);
  const StepInfo before = env.LastInfo();
  try {
    env.JointStep({0, 0});
    FAIL() << "two actions for three UAVs were taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2 actions for 3 UAVs"), std::string::npos) << e.what();
  }
  EXPECT_THROW(env.JointStep({0, 0, 0, 0}), std::invalid_argument);
  try {
    env.JointStep({MoveIndex(s, "up"), 7, 0});
    FAIL() << "action 7 of Discrete(7) was taken";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("action 7 of UAV 1 (\"uav2\")"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(env.JointStep({-1, 0, 0}), std::out_of_range);
  EXPECT_THROW(env.JointStepContinuous({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}), std::out_of_range);
  ExpectSamePositions(env.LastInfo().positions, before.positions, 0);  // UAV 0 did not go up
}

TEST(JointStep, PerUavMasksSeeTheOtherUavs) {
  // urban3's UAVs start 10 m apart; with 5 m steps "right" of UAV 0 would end 5 m from UAV 1:
  // allowed. Brought 4 m apart, it is not.
  const Scenario s = Load("urban3", {"env.fidelity=analytic", "env.action_mask=true",
                                     "uavs.1.position=[49, 45, 40]", "env.step=4"});
  UavPositioningEnv env(s);
  env.Reset(1);
  const ActionMask mask0 = env.ValidActionsOf(0);
  const ActionMask mask1 = env.ValidActionsOf(1);
  ASSERT_EQ(mask0.size(), s.env.actions.size());
  EXPECT_EQ(mask0[static_cast<std::size_t>(MoveIndex(s, "right"))], 0);
  EXPECT_EQ(mask1[static_cast<std::size_t>(MoveIndex(s, "left"))], 0);
  EXPECT_EQ(mask1[static_cast<std::size_t>(MoveIndex(s, "right"))], 1);
  EXPECT_EQ(env.ValidActions(), mask0);  // Step's turn: UAV 0
}

TEST(JointStep, PacketFidelityMeasuresOneInterval) {
  const Scenario s = Load("b", {"env.fidelity=packet", "env.episode_duration=0.5",
                                "env.decision_interval=0.25", "simulation.warmup=0.5"});
  UavPositioningEnv env(s);
  env.Reset(1001);
  const int stay = MoveIndex(s, "stay");
  const JointStepResult first = env.JointStep({stay});
  ExpectConsistent(env, first);
  EXPECT_FALSE(first.truncated);
  const JointStepResult last = env.JointStep({stay});
  EXPECT_TRUE(last.truncated);
  EXPECT_EQ(last.info.n_los, 1);
  EXPECT_GT(last.info.throughput_mbps, 100.0);
}

TEST(JointStep, PacketFidelityMovesTwoUavsAtOnce) {
  // campus2's two UAVs at packet level: each UE has a radio per UAV and is handed over after
  // the joint move, as after Step's.
  const Scenario s = Load("campus2", {"env.fidelity=packet", "env.episode_duration=0.1",
                                      "env.decision_interval=0.1", "simulation.warmup=0.3"});
  UavPositioningEnv env(s);
  env.Reset(1);
  const Placement start = env.LastInfo().positions;
  const int up = MoveIndex(s, "up");
  const JointStepResult m = env.JointStep({up, up});
  ExpectConsistent(env, m);
  for (std::size_t u = 0; u < 2; ++u)
    EXPECT_EQ(m.info.positions[u].z, start[u].z + s.env.step) << "UAV " << u;
  EXPECT_GT(m.info.throughput_mbps, 0.0);
  EXPECT_TRUE(m.truncated);  // one step of 0.1 s
}

}  // namespace
}  // namespace rlpos
