#include "worker/learning/classic_envs/pendulum_env.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "worker/learning/classic_envs/uniform.h"

namespace rlpos {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Python's float modulo: the result has the divisor's sign.
double FloorMod(double x, double m) {
  return x - m * std::floor(x / m);
}

}  // namespace

double NormaliseAngle(double theta) {
  return FloorMod(theta + kPi, 2.0 * kPi) - kPi;
}

PendulumEnv::PendulumEnv(PendulumParameters parameters) : p_(parameters) {}

BoxSpace PendulumEnv::ContinuousActionSpace() const {
  return {{-p_.max_torque}, {p_.max_torque}};
}

BoxSpace PendulumEnv::ObservationSpace() const {
  return {{-1.0, -1.0, -p_.max_speed}, {1.0, 1.0, p_.max_speed}};
}

std::vector<double> PendulumEnv::Observation() const {
  return {std::cos(theta_), std::sin(theta_), theta_dot_};
}

std::vector<double> PendulumEnv::Reset(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  theta_ = UniformBetween(rng, -kPi, kPi);
  theta_dot_ = UniformBetween(rng, -1.0, 1.0);
  steps_ = 0;
  ended_ = false;
  return Observation();
}

void PendulumEnv::SetState(double theta, double theta_dot) {
  theta_ = theta;
  theta_dot_ = theta_dot;
  steps_ = 0;
  ended_ = false;
}

StepResult PendulumEnv::Step(int) {
  throw std::out_of_range("Pendulum takes a continuous torque");
}

StepResult PendulumEnv::StepContinuous(const std::vector<double>& action) {
  if (ended_)
    throw std::logic_error("Pendulum: step after the episode ended; call Reset");
  if (action.size() != 1)
    throw std::invalid_argument("Pendulum: the action is one torque, got " +
                                std::to_string(action.size()) + " values");
  const double u = std::clamp(action[0], -p_.max_torque, p_.max_torque);
  const double angle = NormaliseAngle(theta_);
  const double cost = angle * angle + 0.1 * theta_dot_ * theta_dot_ + 0.001 * u * u;
  // Semi-implicit Euler: the new velocity (clipped) moves the angle.
  const double acceleration = 3.0 * p_.gravity / (2.0 * p_.length) * std::sin(theta_) +
                              3.0 / (p_.mass * p_.length * p_.length) * u;
  theta_dot_ = std::clamp(theta_dot_ + acceleration * p_.dt, -p_.max_speed, p_.max_speed);
  theta_ += theta_dot_ * p_.dt;
  ++steps_;
  StepResult r;
  r.observation = Observation();
  r.reward = -cost;
  r.truncated = steps_ >= p_.max_steps;
  ended_ = r.truncated;
  return r;
}

}  // namespace rlpos
