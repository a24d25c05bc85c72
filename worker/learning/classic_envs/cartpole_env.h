#pragma once
// CartPole-v1 with Gymnasium's published dynamics (Barto, Sutton and Anderson's cart-pole, the
// explicit Euler integration of classic_control/cartpole.py): push the cart left (action 0) or
// right (1) with a fixed force to keep the pole upright. Reward 1 per step, the failing one too;
// terminated when |x| > 2.4 or |theta| > 12 degrees, truncated after 500 steps. Observation
// (x, x_dot, theta, theta_dot); the velocities are unbounded. Reset(seed) draws each state
// component from U(-0.05, 0.05) with its own generator: the same seed, the same episode.
#include <array>
#include <cstdint>

#include "worker/env/gym/env.h"

namespace rlpos {

struct CartPoleParameters {
  double gravity = 9.8;
  double cart_mass = 1.0;
  double pole_mass = 0.1;
  double half_pole_length = 0.5;  // Gymnasium's "length"
  double force = 10.0;
  double tau = 0.02;  // seconds per step
  double x_threshold = 2.4;
  double theta_threshold = 12.0 * 2.0 * 3.14159265358979323846 / 360.0;
  int max_steps = 500;
  double initial_spread = 0.05;
};

class CartPoleEnv : public Env {
 public:
  explicit CartPoleEnv(CartPoleParameters parameters = {});
  DiscreteSpace ActionSpace() const override { return {2}; }
  // Gymnasium's bounds: +-2 x_threshold, +-2 theta_threshold, unbounded velocities.
  BoxSpace ObservationSpace() const override;
  std::vector<double> Reset(std::uint64_t seed) override;
  // Throws std::logic_error after the episode has ended (call Reset), std::out_of_range for an
  // action other than 0 or 1.
  StepResult Step(int action) override;
  const StepInfo& LastInfo() const override { return info_; }
  // Puts the system in (x, x_dot, theta, theta_dot) at the start of an episode, as setting
  // Gymnasium's env.unwrapped.state after a reset (tests, scripted starts).
  void SetState(const std::array<double, 4>& state);

 private:
  void Integrate(double force);

  CartPoleParameters p_;
  std::array<double, 4> state_{};  // x, x_dot, theta, theta_dot
  int steps_ = 0;
  bool ended_ = true;
  StepInfo info_;
};

}  // namespace rlpos
