#pragma once
// Tiny deterministic envs the agents must solve in a test's time.
#include <algorithm>
#include <cmath>

#include "worker/env/gym/env.h"

namespace rlpos {

// States 0..4 on a line; "left"/"right"; reaching 4 pays 1 and ends the episode; 20 steps max.
class ChainEnv : public Env {
 public:
  DiscreteSpace ActionSpace() const override { return {2}; }
  BoxSpace ObservationSpace() const override { return {{0}, {4}}; }
  std::vector<double> Reset(std::uint64_t) override {
    state_ = 0;
    steps_ = 0;
    info_.positions = {{0, 0, 0}};
    return {0.0};
  }
  StepResult Step(int action) override {
    state_ = std::clamp(state_ + (action == 1 ? 1 : -1), 0, 4);
    ++steps_;
    info_.positions = {{static_cast<double>(state_), 0, 0}};
    StepResult r;
    r.observation = {static_cast<double>(state_)};
    r.terminated = state_ == 4;
    r.reward = r.terminated ? 1.0 : 0.0;
    r.truncated = steps_ >= 20;
    r.info = info_;
    return r;
  }
  const StepInfo& LastInfo() const override { return info_; }

 private:
  int state_ = 0;
  int steps_ = 0;
  StepInfo info_;
};

// A point on [0, 10] moved by a displacement in [-1, 1]; the reward is higher the closer it is to
// 7 (-|x - 7| / 10); 20 steps per episode, from 2.
class PointEnv : public Env {
 public:
  static constexpr double kTarget = 7.0;
  DiscreteSpace ActionSpace() const override { return {0}; }
  BoxSpace ContinuousActionSpace() const override { return {{-1}, {1}}; }
  BoxSpace ObservationSpace() const override { return {{0}, {10}}; }
  std::vector<double> Reset(std::uint64_t) override {
    x_ = 2.0;
    steps_ = 0;
    info_.positions = {{x_, 0, 0}};
    return {x_};
  }
  StepResult Step(int) override { throw std::out_of_range("continuous actions only"); }
  StepResult StepContinuous(const std::vector<double>& action) override {
    if (!ContinuousActionSpace().Contains(action))
      throw std::out_of_range("action outside [-1, 1]");
    x_ = std::clamp(x_ + action[0], 0.0, 10.0);
    ++steps_;
    info_.positions = {{x_, 0, 0}};
    StepResult r;
    r.observation = {x_};
    r.reward = -std::abs(x_ - kTarget) / 10.0;
    r.truncated = steps_ >= 20;
    r.info = info_;
    return r;
  }
  const StepInfo& LastInfo() const override { return info_; }

 private:
  double x_ = 2.0;
  int steps_ = 0;
  StepInfo info_;
};

// One state, one action paying 1; every episode is one step, ended by termination or, with
// `truncate`, by the time limit: the value of the state is 1 if the end is terminal and
// 1 / (1 - gamma) if the episode was only cut short (the state goes on).
class OneStepEnv : public Env {
 public:
  explicit OneStepEnv(bool truncate) : truncate_(truncate) {}
  DiscreteSpace ActionSpace() const override { return {1}; }
  BoxSpace ObservationSpace() const override { return {{0}, {1}}; }
  std::vector<double> Reset(std::uint64_t) override { return {0.5}; }
  StepResult Step(int) override {
    StepResult r;
    r.observation = {0.5};
    r.reward = 1.0;
    r.terminated = !truncate_;
    r.truncated = truncate_;
    return r;
  }
  const StepInfo& LastInfo() const override { return info_; }

 private:
  bool truncate_;
  StepInfo info_;
};

}  // namespace rlpos
