// CartPole-v1: Gymnasium's dynamics step by step, its termination and truncation, seeding.
#include "worker/learning/classic_envs/cartpole_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/worker/learning/classic_envs/seeded_reset.h"

namespace rlpos {
namespace {

// Each component of a state, to 1e-12.
void ExpectState(const std::vector<double>& got, const std::array<double, 4>& want) {
  ASSERT_EQ(got.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(got[i], want[i], 1e-12) << "component " << i;
}

TEST(CartPole, StepsFollowGymnasiumsEulerEquations) {
  // Expected: the published equations (cartpole.py, kinematics_integrator "euler") evaluated in
  // double precision, independently of this code.
  CartPoleEnv env;
  env.Reset(1);
  env.SetState({0.01, -0.02, 0.03, 0.04});
  ExpectState(env.Step(1).observation, {0.009600000000000001, 0.17467919574755525,
                                        0.030799999999999998, -0.24306871796000815});
  ExpectState(env.Step(1).observation, {0.013093583914951107, 0.3693479760579556,
                                        0.025938625640799833, -0.5258796280501484});
  const StepResult r = env.Step(0);
  ExpectState(r.observation, {0.02048054343611022, 0.17387081260481596, 0.015421033079796864,
                              -0.22513741609237475});
  EXPECT_EQ(r.reward, 1.0);
  EXPECT_FALSE(r.terminated);
  EXPECT_FALSE(r.truncated);
}

TEST(CartPole, ResetDrawsEachComponentFromTheSeed) {
  CartPoleEnv a;
  CartPoleEnv b;
  const auto first = ExpectResetFollowsTheSeed(a, b, 7);
  for (double s : first) {
    EXPECT_GE(s, -0.05);
    EXPECT_LT(s, 0.05);
  }
}

TEST(CartPole, FallingTerminatesWithTheRewardOfTheFailingStep) {
  CartPoleEnv env;
  env.Reset(3);
  int steps = 0;
  StepResult r;
  do {
    r = env.Step(1);  // always right: the pole falls left
    ++steps;
    EXPECT_EQ(r.reward, 1.0);
  } while (!r.terminated && steps < 500);
  EXPECT_TRUE(r.terminated);
  EXPECT_FALSE(r.truncated);
  EXPECT_LT(steps, 50);
  EXPECT_TRUE(std::abs(r.observation[2]) > 12.0 * M_PI / 180.0 || std::abs(r.observation[0]) > 2.4);
  EXPECT_THROW(env.Step(0), std::logic_error);
  EXPECT_THROW(env.Step(2), std::logic_error);  // ended first
}

TEST(CartPole, ABalancedPoleIsTruncatedAt500StepsNotTerminated) {
  CartPoleEnv env;
  std::vector<double> obs = env.Reset(5);
  StepResult r;
  for (int step = 1; step <= 500; ++step) {
    // Push towards where the pole leans (and falls): keeps it up for the whole episode.
    const double lean = obs[2] + 0.5 * obs[3] + 0.01 * obs[0] + 0.1 * obs[1];
    r = env.Step(lean > 0 ? 1 : 0);
    obs = r.observation;
    ASSERT_FALSE(r.terminated) << "fell at step " << step;
    EXPECT_EQ(r.truncated, step == 500);
  }
  EXPECT_THROW(env.Step(0), std::logic_error);
}

TEST(CartPole, RejectsAnActionOutsideItsSpace) {
  CartPoleEnv env;
  EXPECT_THROW(env.Step(0), std::logic_error);  // before a reset
  env.Reset(1);
  EXPECT_THROW(env.Step(2), std::out_of_range);
  EXPECT_THROW(env.Step(-1), std::out_of_range);
}

TEST(CartPole, VelocitiesAreUnboundedAndReachTheNetworkUnscaled) {
  const BoxSpace box = CartPoleEnv().ObservationSpace();
  EXPECT_TRUE(std::isinf(box.high[1]));
  EXPECT_TRUE(std::isinf(box.high[3]));
  EXPECT_DOUBLE_EQ(box.high[0], 4.8);
  const auto n = box.Normalise({2.4, 1.5, -0.2, -3.0});
  EXPECT_FLOAT_EQ(n[0], 0.5f);
  EXPECT_FLOAT_EQ(n[1], 1.5f);
  EXPECT_NEAR(n[2], -0.2 / (24.0 * M_PI / 180.0), 1e-6);
  EXPECT_FLOAT_EQ(n[3], -3.0f);
}

}  // namespace
}  // namespace rlpos
