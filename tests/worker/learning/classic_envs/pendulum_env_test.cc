// Pendulum-v1: Gymnasium's dynamics and reward, truncation without termination, seeding.
#include "worker/learning/classic_envs/pendulum_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/worker/learning/classic_envs/seeded_reset.h"

namespace rlpos {
namespace {

// Expected values: the published equations (pendulum.py) evaluated in double precision,
// independently of this code.
TEST(Pendulum, StepsFollowGymnasiumsEquationsAndCostTheStateBeforeTheStep) {
  PendulumEnv env;
  env.Reset(1);
  env.SetState(3.0, 0.5);
  StepResult r = env.StepContinuous({5.0});  // clipped to 2
  EXPECT_NEAR(r.reward, -9.029, 1e-12);
  const double theta = 3.0452920003022452;
  const double theta_dot = 0.9058400060449003;
  ASSERT_EQ(r.observation.size(), 3u);
  EXPECT_NEAR(r.observation[0], std::cos(theta), 1e-12);
  EXPECT_NEAR(r.observation[1], std::sin(theta), 1e-12);
  EXPECT_NEAR(r.observation[2], theta_dot, 1e-12);

  env.SetState(-2.5, -7.9);
  r = env.StepContinuous({-1.0});
  EXPECT_NEAR(r.reward, -12.491999999999999, 1e-12);
  EXPECT_DOUBLE_EQ(r.observation[2], -8.0);  // the speed is clipped
  EXPECT_NEAR(r.observation[1], std::sin(-2.9), 1e-12);

  env.SetState(5.0, 0.0);  // past pi: the cost takes the angle normalised, 5 - 2 pi
  r = env.StepContinuous({0.0});
  EXPECT_NEAR(r.reward, -1.646564532561569, 1e-12);
  EXPECT_NEAR(r.observation[2], -0.7191932059973539, 1e-12);
  EXPECT_NEAR(r.observation[0], std::cos(4.964040339700133), 1e-12);
}

TEST(Pendulum, AnglesAreNormalisedOntoMinusPiToPi) {
  EXPECT_NEAR(NormaliseAngle(3 * M_PI), -M_PI, 1e-12);
  EXPECT_NEAR(NormaliseAngle(M_PI), -M_PI, 1e-12);
  EXPECT_NEAR(NormaliseAngle(-M_PI), -M_PI, 1e-12);
  EXPECT_NEAR(NormaliseAngle(4.0), 4.0 - 2 * M_PI, 1e-12);
  EXPECT_NEAR(NormaliseAngle(0.5), 0.5, 1e-12);
}

TEST(Pendulum, TruncatedAfter200StepsAndNeverTerminated) {
  PendulumEnv env;
  env.Reset(2);
  for (int step = 1; step <= 200; ++step) {
    const StepResult r = env.StepContinuous({std::sin(step * 0.3) * 2.0});
    ASSERT_FALSE(r.terminated);
    EXPECT_EQ(r.truncated, step == 200);
    EXPECT_LE(r.reward, 0.0);
    EXPECT_GE(r.reward, -16.2736044);
  }
  EXPECT_THROW(env.StepContinuous({0.0}), std::logic_error);
}

TEST(Pendulum, ResetDrawsTheAngleAndSpeedFromTheSeed) {
  PendulumEnv a;
  PendulumEnv b;
  ExpectResetFollowsTheSeed(a, b, 11);
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const auto obs = a.Reset(seed);
    EXPECT_NEAR(obs[0] * obs[0] + obs[1] * obs[1], 1.0, 1e-12);
    EXPECT_GE(obs[2], -1.0);
    EXPECT_LT(obs[2], 1.0);
  }
}

TEST(Pendulum, TakesOneContinuousTorque) {
  PendulumEnv env;
  EXPECT_EQ(env.ActionSpace().n, 0);
  EXPECT_DOUBLE_EQ(env.ContinuousActionSpace().high[0], 2.0);
  env.Reset(1);
  EXPECT_THROW(env.Step(0), std::out_of_range);
  EXPECT_THROW(env.StepContinuous({1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
