// FlyGreedy reads a greedy episode's end off its cycle: the same end as flying it all, for every
// shape of path (lead-in, period, the episode's length), and the whole flight where the env
// cannot tell its state.
#include "worker/agent/greedy_flight.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace rlpos {
namespace {

// States 0..n-1; action a moves to state a. The observation is the state; so are the reward
// (state / 10) and the info (position x and n_los). Only the time limit ends an episode.
class JumpEnv : public Env {
 public:
  JumpEnv(int states, int episode_steps, bool tells_state)
      : states_(states), episode_steps_(episode_steps), tells_state_(tells_state) {}
  DiscreteSpace ActionSpace() const override { return {states_}; }
  BoxSpace ObservationSpace() const override {
    const double inf = std::numeric_limits<double>::infinity();
    return {{-inf}, {inf}};  // passed through as it is
  }
  std::vector<double> Reset(std::uint64_t) override {
    state_ = 0;
    steps_ = 0;
    Observe();
    return {0.0};
  }
  StepResult Step(int action) override {
    state_ = action;
    ++steps_;
    Observe();
    StepResult r;
    r.observation = {static_cast<double>(state_)};
    r.reward = state_ / 10.0;
    r.truncated = steps_ >= episode_steps_;
    r.info = info_;
    return r;
  }
  const StepInfo& LastInfo() const override { return info_; }
  std::optional<DeterminingState> Determining() const override {
    if (!tells_state_)
      return std::nullopt;
    return DeterminingState{{static_cast<std::uint64_t>(state_)}, episode_steps_ - steps_};
  }
  int steps() const { return steps_; }

 private:
  void Observe() {
    info_.positions = {{static_cast<double>(state_), 0, 0}};
    info_.n_los = state_;
  }
  int states_;
  int episode_steps_;
  bool tells_state_;
  int state_ = 0;
  int steps_ = 0;
  StepInfo info_;
};

// Greedy by a table: in state s it goes to next[s].
class TableAgent : public Agent {
 public:
  explicit TableAgent(std::vector<int> next) : next_(std::move(next)) {}
  std::string Algorithm() const override { return "table"; }
  int Act(const std::vector<float>& observation, const ActionMask&, bool) override {
    return next_.at(static_cast<std::size_t>(observation.at(0)));
  }
  std::optional<double> Observe(Transition) override {
    throw std::logic_error("a greedy flight learns nothing");
  }
  void KeepPolicy() override {}
  void RestoreKeptPolicy() override {}
  void Save(const std::string&) const override {}
  void Load(const std::string&) override {}

 private:
  std::vector<int> next_;
};

// 0 -> 1 -> ... -> lead_in, then a ring of `period` states from there (period 1: it stays).
std::vector<int> PathWith(int lead_in, int period) {
  const int states = lead_in + period;
  std::vector<int> next(static_cast<std::size_t>(states));
  for (int s = 0; s < states; ++s)
    next[static_cast<std::size_t>(s)] = s + 1 < states ? s + 1 : lead_in;
  return next;
}

TEST(GreedyFlight, EndsWhereTheWholeFlightEndsForEveryLeadInPeriodAndLength) {
  for (int lead_in = 0; lead_in <= 4; ++lead_in) {
    for (int period = 1; period <= 5; ++period) {
      for (int steps = 1; steps <= 23; ++steps) {
        const std::string where = "lead-in " + std::to_string(lead_in) + ", period " +
                                  std::to_string(period) + ", " + std::to_string(steps) + " steps";
        const std::vector<int> next = PathWith(lead_in, period);
        JumpEnv whole_env(lead_in + period, steps, true);
        TableAgent whole_agent(next);
        const EpisodeRecord whole = RunEpisode(whole_env, whole_agent, 1, false);
        JumpEnv env(lead_in + period, steps, true);
        TableAgent agent(next);
        const GreedyFlight flight = FlyGreedy(env, agent, 1, {});
        EXPECT_EQ(flight.final_info.positions.at(0).x, whole.final_info.positions.at(0).x) << where;
        EXPECT_EQ(flight.final_info.n_los, whole.final_info.n_los) << where;
        EXPECT_EQ(flight.final_reward, whole.final_reward) << where;
        EXPECT_EQ(flight.steps, whole.steps) << where;
        // It stops at the first state met again: after lead_in + period steps at most.
        EXPECT_EQ(flight.steps_flown, std::min(steps, lead_in + period)) << where;
        EXPECT_EQ(env.steps(), flight.steps_flown) << where;
      }
    }
  }
}

TEST(GreedyFlight, KeepsAStepLimitShorterThanTheEpisode) {
  JumpEnv env(6, 100, true);
  TableAgent agent(PathWith(2, 4));
  EpisodeOptions options;
  options.max_steps = 9;  // 0 1 2 3 4 5 2 3 4 [5]
  const GreedyFlight flight = FlyGreedy(env, agent, 1, options);
  EXPECT_EQ(flight.steps, 9);
  EXPECT_EQ(flight.final_info.n_los, 5);
}

TEST(GreedyFlight, FliesTheWholeEpisodeWhereTheEnvCannotTellItsState) {
  JumpEnv env(3, 50, false);
  TableAgent agent(PathWith(1, 2));
  const GreedyFlight flight = FlyGreedy(env, agent, 1, {});
  EXPECT_EQ(flight.steps_flown, 50);
  EXPECT_EQ(env.steps(), 50);
  EXPECT_EQ(flight.final_info.n_los, 2);  // 0 [1 2]...: step 50 is even, in state 2
}

}  // namespace
}  // namespace rlpos
