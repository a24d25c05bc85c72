#pragma once
// Pendulum-v1 with Gymnasium's published dynamics (classic_control/pendulum.py): swing a pendulum
// up and hold it with a torque in [-2, 2]. Reward -(theta^2 + 0.1 theta_dot^2 + 0.001 u^2) with
// theta normalised to [-pi, pi) (0 upright) and u the clipped torque; it never terminates and is
// truncated after 200 steps. Observation (cos theta, sin theta, theta_dot). Reset(seed) draws
// theta from U(-pi, pi) and theta_dot from U(-1, 1) with its own generator.
#include <cstdint>

#include "worker/env/gym/env.h"

namespace rlpos {

struct PendulumParameters {
  double max_speed = 8.0;
  double max_torque = 2.0;
  double dt = 0.05;
  double gravity = 10.0;
  double mass = 1.0;
  double length = 1.0;
  int max_steps = 200;
};

// theta mapped onto [-pi, pi), as Gymnasium's angle_normalize.
double NormaliseAngle(double theta);

class PendulumEnv : public Env {
 public:
  explicit PendulumEnv(PendulumParameters parameters = {});
  DiscreteSpace ActionSpace() const override { return {0}; }
  BoxSpace ContinuousActionSpace() const override;
  BoxSpace ObservationSpace() const override;
  std::vector<double> Reset(std::uint64_t seed) override;
  StepResult Step(int action) override;  // throws: the torque is continuous
  // The torque is clipped to [-max_torque, max_torque]. Throws std::logic_error after the
  // episode has ended (call Reset), std::invalid_argument for an action of another size.
  StepResult StepContinuous(const std::vector<double>& action) override;
  const StepInfo& LastInfo() const override { return info_; }
  // Puts the pendulum at (theta, theta_dot) at the start of an episode (tests, scripted starts).
  void SetState(double theta, double theta_dot);

 private:
  std::vector<double> Observation() const;

  PendulumParameters p_;
  double theta_ = 0.0;
  double theta_dot_ = 0.0;
  int steps_ = 0;
  bool ended_ = true;
  StepInfo info_;
};

}  // namespace rlpos
