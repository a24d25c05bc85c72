// FlyGreedy reads a greedy episode's end off its cycle: the same end as flying it all, for every
// shape of path (lead-in, period, the episode's length), and the whole flight where the env
// cannot tell its state. FlyGreedyToBest keeps the best step of the same flight and stops when
// patience, a state met again, a step limit or the episode says so. FlyGreedyFromStarts keeps the
// best of such flights from seeded starts within a step budget; FlyGeneralPlacement flies one
// for one UAV and several for several.
#include "worker/learning/agent_base/greedy_flight.h"

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
  JumpEnv(int states, int episode_steps, bool tells_state, std::size_t agents = 1)
      : states_(states),
        episode_steps_(episode_steps),
        tells_state_(tells_state),
        agents_(agents) {}
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
  // A drawn start: state seed mod states.
  std::vector<double> Reset(std::uint64_t seed, const ResetOptions& options) override {
    Reset(seed);
    if (options.random_start) {
      state_ = static_cast<int>(seed % static_cast<std::uint64_t>(states_));
      Observe();
    }
    ++resets_;
    return {static_cast<double>(state_)};
  }
  std::size_t AgentCount() const override { return agents_; }
  StepResult Step(int action) override {
    state_ = action;
    ++steps_;
    ++all_steps_;
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
  int resets() const { return resets_; }
  int all_steps() const { return all_steps_; }  // since it was made

 private:
  void Observe() {
    info_.positions = {{static_cast<double>(state_), 0, 0}};
    info_.n_los = state_;
  }
  int states_;
  int episode_steps_;
  bool tells_state_;
  std::size_t agents_;
  int resets_ = 0;
  int all_steps_ = 0;
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

// 0 -> 5 -> 1 -> 2 -> 3 -> 4 -> 6 -> 7 -> 6 ...: the reward (state / 10) falls after the first
// step, rises past it only at the sixth, peaks at the seventh, then repeats 6 7.
const std::vector<int> kDipThenPeak = {5, 2, 3, 4, 6, 1, 7, 6};

GreedyFlight ToBest(int patience, int max_steps = 0, int episode_steps = 100) {
  JumpEnv env(8, episode_steps, true);
  TableAgent agent(kDipThenPeak);
  EpisodeOptions options;
  options.max_steps = max_steps;
  const GreedyFlight flight = FlyGreedyToBest(env, agent, 1, options, patience);
  EXPECT_EQ(env.steps(), flight.steps_flown);
  return flight;
}

TEST(GreedyFlightToBest, KeepsTheBestStepNotTheLast) {
  // No patience: it flies until state 6 comes again (step 8), and keeps step 7's state 7.
  const GreedyFlight all = ToBest(0);
  EXPECT_EQ(all.steps_flown, 8);
  EXPECT_EQ(all.best_step, 7);
  EXPECT_EQ(all.final_info.n_los, 7);
  EXPECT_EQ(all.final_info.positions.at(0).x, 7.0);
  EXPECT_DOUBLE_EQ(all.final_reward, 0.7);
}

TEST(GreedyFlightToBest, StopsAfterThePatienceWithoutAHigherReward) {
  // Steps 2-5 fall short of step 1's 0.5: four steps of patience end the flight at step 5.
  const GreedyFlight four = ToBest(4);
  EXPECT_EQ(four.steps_flown, 5);
  EXPECT_EQ(four.best_step, 1);
  EXPECT_EQ(four.final_info.n_los, 5);
  // Five are enough to see step 6 rise above it; then the peak, then the state met again.
  const GreedyFlight five = ToBest(5);
  EXPECT_EQ(five.steps_flown, 8);
  EXPECT_EQ(five.final_info.n_los, 7);
}

TEST(GreedyFlightToBest, KeepsAStepLimitAndTheEpisodesEnd) {
  EXPECT_EQ(ToBest(0, 3).steps_flown, 3);
  EXPECT_EQ(ToBest(0, 3).final_info.n_los, 5);
  EXPECT_EQ(ToBest(0, 0, 6).steps_flown, 6);
  EXPECT_EQ(ToBest(0, 0, 6).final_info.n_los, 6);
}

TEST(GreedyFlightToBest, KeepsTheFirstOfEqualRewards) {
  // The env cannot tell its state, so 0 -> 2 -> 1 -> 2 -> 1 ... flies on: step 3 only equals
  // step 1's reward, so three steps of patience end it at step 4.
  JumpEnv env(3, 50, false);
  TableAgent agent({2, 2, 1});
  const GreedyFlight flight = FlyGreedyToBest(env, agent, 1, {}, 3);
  EXPECT_EQ(flight.best_step, 1);
  EXPECT_EQ(flight.steps_flown, 4);
  EXPECT_EQ(flight.final_info.n_los, 2);
}

// From the baseline (state 0) the flight settles at 1; from the start seed 2 draws (state 2) it
// settles at 4, from seed 3's (state 3) at 6: two steps, one move and the state met again. From
// states 4 to 7 it stays, one step.
const std::vector<int> kStartDecides = {1, 1, 4, 6, 4, 5, 6, 7};

GreedyFlight FromStarts(int flights, int budget) {
  JumpEnv env(8, 100, true);
  TableAgent agent(kStartDecides);
  const GreedyFlight flight = FlyGreedyFromStarts(env, agent, 1, {}, 0, flights, budget);
  EXPECT_EQ(env.all_steps(), flight.steps_flown);  // every flight's steps
  return flight;
}

TEST(GreedyFlightFromStarts, OneFlightIsTheFlightFromTheBaseline) {
  const GreedyFlight one = FromStarts(1, 1000);
  EXPECT_EQ(one.steps_flown, 2);
  EXPECT_EQ(one.final_info.n_los, 1);
  EXPECT_DOUBLE_EQ(one.final_reward, 0.1);
}

TEST(GreedyFlightFromStarts, KeepsTheBestFlightOfTheStartsDrawnFromTheSeedsAfterItsOwn) {
  const GreedyFlight two = FromStarts(2, 1000);
  EXPECT_EQ(two.final_info.n_los, 4);  // seed 1 + 1
  EXPECT_EQ(two.steps_flown, 4);
  const GreedyFlight three = FromStarts(3, 1000);
  EXPECT_EQ(three.final_info.n_los, 6);  // seed 1 + 2
  EXPECT_DOUBLE_EQ(three.final_reward, 0.6);
  EXPECT_EQ(three.best_step, 1);
  EXPECT_EQ(three.steps_flown, 6);
  // States 4 and 5 settle where they start: no better than 6, so 6 stays the placement.
  EXPECT_EQ(FromStarts(5, 1000).final_info.n_los, 6);
}

TEST(GreedyFlightFromStarts, StartsNoFlightOnceTheBudgetIsSpentAndCutsTheLastAtIt) {
  // The first flight is flown whatever the budget.
  EXPECT_EQ(FromStarts(8, 1).steps_flown, 2);
  EXPECT_EQ(FromStarts(8, 2).final_info.n_los, 1);
  // Three steps: the second flight is cut after its first, which already reaches 4.
  const GreedyFlight three = FromStarts(8, 3);
  EXPECT_EQ(three.steps_flown, 3);
  EXPECT_EQ(three.final_info.n_los, 4);
  EXPECT_EQ(FromStarts(8, 5).final_info.n_los, 6);
  EXPECT_EQ(FromStarts(8, 5).steps_flown, 5);
}

TEST(GreedyFlightFromStarts, RefusesAPlacementOfNoFlight) {
  JumpEnv env(8, 100, true);
  TableAgent agent(kStartDecides);
  EXPECT_THROW(FlyGreedyFromStarts(env, agent, 1, {}, 0, 0, 1000), std::invalid_argument);
}

TEST(GeneralPlacementFlight, OneUavFliesOnceFromTheBaselineSeveralFromSeveralStarts) {
  JumpEnv one(8, 100, true, 1);
  TableAgent agent(kStartDecides);
  const GreedyFlight alone = FlyGeneralPlacement(one, agent, 1, {});
  EXPECT_EQ(one.resets(), 1);
  EXPECT_EQ(alone.final_info.n_los, 1);
  JumpEnv two(8, 100, true, 2);
  const GreedyFlight several = FlyGeneralPlacement(two, agent, 1, {});
  EXPECT_EQ(two.resets(), kGeneralPlacementFlights);
  EXPECT_EQ(several.final_info.n_los, 7);  // state 7 is drawn by seed 7 = 1 + 6
}

}  // namespace
}  // namespace rlpos
