#include "worker/learning/classic_envs/cartpole_env.h"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "worker/learning/classic_envs/uniform.h"

namespace rlpos {

CartPoleEnv::CartPoleEnv(CartPoleParameters parameters) : p_(parameters) {}

BoxSpace CartPoleEnv::ObservationSpace() const {
  const double inf = std::numeric_limits<double>::infinity();
  const double x = 2.0 * p_.x_threshold;
  const double theta = 2.0 * p_.theta_threshold;
  return {{-x, -inf, -theta, -inf}, {x, inf, theta, inf}};
}

std::vector<double> CartPoleEnv::Reset(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (double& s : state_)
    s = UniformBetween(rng, -p_.initial_spread, p_.initial_spread);
  steps_ = 0;
  ended_ = false;
  return {state_.begin(), state_.end()};
}

void CartPoleEnv::SetState(const std::array<double, 4>& state) {
  state_ = state;
  steps_ = 0;
  ended_ = false;
}

// One explicit Euler step of the cart-pole equations of motion (positions advance with the
// velocities of the start of the step, as Gymnasium's "euler" integrator).
void CartPoleEnv::Integrate(double force) {
  const auto [x, x_dot, theta, theta_dot] = state_;
  const double total_mass = p_.cart_mass + p_.pole_mass;
  const double pole_mass_length = p_.pole_mass * p_.half_pole_length;
  const double cos_theta = std::cos(theta);
  const double sin_theta = std::sin(theta);
  const double temp = (force + pole_mass_length * theta_dot * theta_dot * sin_theta) / total_mass;
  const double theta_acc =
      (p_.gravity * sin_theta - cos_theta * temp) /
      (p_.half_pole_length * (4.0 / 3.0 - p_.pole_mass * cos_theta * cos_theta / total_mass));
  const double x_acc = temp - pole_mass_length * theta_acc * cos_theta / total_mass;
  state_ = {x + p_.tau * x_dot, x_dot + p_.tau * x_acc, theta + p_.tau * theta_dot,
            theta_dot + p_.tau * theta_acc};
}

StepResult CartPoleEnv::Step(int action) {
  if (ended_)
    throw std::logic_error("CartPole: step after the episode ended; call Reset");
  if (!ActionSpace().Contains(action))
    throw std::out_of_range("CartPole: action " + std::to_string(action) + " is not 0 or 1");
  Integrate(action == 1 ? p_.force : -p_.force);
  ++steps_;
  const double x = state_[0];
  const double theta = state_[2];
  StepResult r;
  r.observation.assign(state_.begin(), state_.end());
  r.reward = 1.0;
  r.terminated = x < -p_.x_threshold || x > p_.x_threshold || theta < -p_.theta_threshold ||
                 theta > p_.theta_threshold;
  r.truncated = steps_ >= p_.max_steps;
  ended_ = r.terminated || r.truncated;
  return r;
}

}  // namespace rlpos
