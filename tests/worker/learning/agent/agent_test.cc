// Replay buffer, epsilon schedule and the DQN agent on a tiny known MDP.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/worker/learning/agent/plain_training.h"
#include "tests/worker/learning/agent/policy_checks.h"
#include "tests/worker/learning/agent/tiny_envs.h"
#include "worker/learning/agent/dqn_agent.h"
#include "worker/learning/agent_base/replay_buffer.h"
#include "worker/learning/agent_base/running_moments.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {
namespace {

TEST(ReplayBuffer, RingOverwritesTheOldest) {
  ReplayBuffer buffer(3);
  for (int i = 0; i < 5; ++i)
    buffer.Add({{static_cast<float>(i)}, i, 0.0f, {0.0f}, false, {}, {}, false});
  ASSERT_EQ(buffer.Size(), 3u);
  std::vector<int> actions;
  for (std::size_t i = 0; i < buffer.Size(); ++i)
    actions.push_back(buffer.At(i).action);
  std::sort(actions.begin(), actions.end());
  EXPECT_EQ(actions, (std::vector<int>{2, 3, 4}));
}

TEST(ReplayBuffer, SeededSamplingIsReproducible) {
  ReplayBuffer buffer(100);
  for (int i = 0; i < 100; ++i)
    buffer.Add({{0.0f}, i, 0.0f, {0.0f}, false, {}, {}, false});
  std::mt19937_64 a(7), b(7), c(8);
  EXPECT_EQ(buffer.SampleIndices(64, a), buffer.SampleIndices(64, b));
  std::mt19937_64 a2(7);
  EXPECT_NE(buffer.SampleIndices(64, a2), buffer.SampleIndices(64, c));
  EXPECT_THROW(ReplayBuffer(0), std::invalid_argument);
}

TEST(EpsilonSchedule, LinearThenFlat) {
  const EpsilonSchedule constant{1.0, 0.1, 0};
  EXPECT_DOUBLE_EQ(constant.At(0), 1.0);
  EXPECT_DOUBLE_EQ(constant.At(1000000), 1.0);  // the paper: epsilon 1 throughout
  const EpsilonSchedule decay{1.0, 0.1, 100};
  EXPECT_DOUBLE_EQ(decay.At(0), 1.0);
  EXPECT_NEAR(decay.At(50), 0.55, 1e-12);
  EXPECT_DOUBLE_EQ(decay.At(100), 0.1);
  EXPECT_DOUBLE_EQ(decay.At(500), 0.1);
}

TEST(RunningMoments, MeanSpreadAndStandardise) {
  RunningMoments m;
  m.Add(3.0);
  EXPECT_DOUBLE_EQ(m.Mean(), 3.0);
  EXPECT_DOUBLE_EQ(m.StdDev(), 0.0);
  EXPECT_FLOAT_EQ(m.Standardise(4.0), 1.0f);  // no spread yet: only centred
  for (double x : {1.0, 5.0, 7.0})
    m.Add(x);  // 3, 1, 5, 7
  EXPECT_DOUBLE_EQ(m.Mean(), 4.0);
  EXPECT_NEAR(m.StdDev(), std::sqrt(20.0 / 3.0), 1e-12);  // sample standard deviation
  EXPECT_NEAR(m.Standardise(4.0 + std::sqrt(20.0 / 3.0)), 1.0f, 1e-6);
}

AgentSpec SmallSpec(std::uint64_t seed, int episodes = 60) {
  AgentSpec spec = PlainTrainingSpec("dqn", seed, episodes);
  DqnSpec& dqn = spec.dqn;
  dqn.learning_rate = 1e-2;
  dqn.replay_capacity = 10000;
  dqn.batch_size = 32;
  dqn.gamma = 0.9;
  dqn.warmup_steps = 32;
  dqn.target_update_interval = 50;
  dqn.epsilon_end = 1.0;  // random exploration throughout, as in the paper
  return spec;
}

TEST(DqnAgent, DefaultsAreThePapersAndTheTargetLagsAnEpisode) {
  const AgentSpec spec;
  // Table II of the paper: two layers of 32, a replay of 10^6 and batches of 64.
  EXPECT_EQ(spec.hidden, (std::vector<int>{32, 32}));
  EXPECT_EQ(spec.dqn.replay_capacity, 1000000);
  EXPECT_EQ(spec.dqn.batch_size, 64);
  // Not the paper's 1e-2: 1e-3 holds with three UAVs (docs/agents.md).
  EXPECT_DOUBLE_EQ(spec.dqn.learning_rate, 1e-3);
  // Not the paper's 10 episodes of 1,000 steps from the baseline: 1,000 of 25 steps from
  // random starts, a greedy checkpoint every 50 (chosen on generated scenarios, docs/agents.md).
  EXPECT_EQ(spec.train_episodes, 1000);
  EXPECT_EQ(spec.train_episode_steps, 25);
  EXPECT_TRUE(spec.exploring_starts);
  EXPECT_EQ(spec.eval_interval, 50);
  // Not the paper's (epsilon 1 throughout): from 1 to 0.05 over the first 8,000 steps.
  EXPECT_DOUBLE_EQ(spec.dqn.epsilon_start, 1.0);
  EXPECT_DOUBLE_EQ(spec.dqn.epsilon_end, 0.05);
  EXPECT_EQ(spec.dqn.epsilon_decay_steps, 8000);
  // Not the paper's: the target network is refreshed once per paper episode (100 s / 0.1 s),
  // which is what let scenario A's greedy policy beat the baseline (docs/agents.md).
  EXPECT_EQ(spec.dqn.target_update_interval, 1000);
  // Not the paper's either: Double DQN and standardised rewards (docs/agents.md).
  EXPECT_TRUE(spec.dqn.double_dqn);
  EXPECT_TRUE(spec.normalise_rewards);
}

TEST(DqnAgent, LearnsOnlyOnceTheBufferHoldsABatch) {
  AgentSpec spec = SmallSpec(1);
  spec.dqn.warmup_steps = 0;  // a scenario may ask for none: the batch alone holds learning back
  spec.dqn.batch_size = 8;
  DqnAgent agent(spec, 1, 2);
  for (int i = 1; i <= 8; ++i) {
    Transition t;
    t.observation = {0.5f};
    t.action = i % 2;
    t.reward = 1.0f;
    t.next_observation = {0.5f};
    t.next_mask = {1, 1};
    const std::optional<double> loss = agent.Observe(std::move(t));
    if (i < 8) {
      EXPECT_FALSE(loss.has_value()) << "learned from " << i << " transitions, fewer than a batch";
    } else {
      EXPECT_TRUE(loss.has_value()) << "did not learn from a full batch";
    }
  }
}

TEST(DqnAgent, ActsOnlyAmongAllowedActions) {
  DqnAgent agent(SmallSpec(4), 1, 3);  // epsilon 1: exploring picks uniformly
  const ActionMask no_middle{1, 0, 1};
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 600; ++i)
    ++counts[agent.Act({0.0f}, no_middle, true)];
  EXPECT_EQ(counts[1], 0);
  EXPECT_GT(counts[0], 200);
  EXPECT_GT(counts[2], 200);
  // Greedy: the best allowed action, not the best one.
  const auto q = agent.QValues({0.0f});
  const int best = static_cast<int>(std::max_element(q.begin(), q.end()) - q.begin());
  ActionMask without_best{1, 1, 1};
  without_best[best] = 0;
  const int got = agent.Act({0.0f}, without_best, false);
  EXPECT_NE(got, best);
  for (int a = 0; a < 3; ++a) {
    if (a != best) {
      EXPECT_GE(q[got], q[a]);
    }
  }
  EXPECT_THROW(agent.Act({0.0f}, ActionMask{0, 0, 0}, false), std::invalid_argument);
}

// Q(s0, a0) after learning from: s0 -a0-> s1 (reward 0); s1 -a0-> s1 (reward 0); s1 -a1->
// end (reward 10). After s0 only a0 is allowed in s1, so the bootstrap of s0 must not see
// Q(s1, a1) = 10.
float LearnedValueBehindAMaskedAction(bool mask_the_jackpot) {
  AgentSpec spec = SmallSpec(2);
  spec.normalise_rewards = false;
  spec.dqn.target_update_interval = 20;
  DqnAgent agent(spec, 1, 2);
  const ActionMask only_a0 = mask_the_jackpot ? ActionMask{1, 0} : ActionMask{};
  for (int i = 0; i < 700; ++i) {
    agent.Observe({{-1.0f}, 0, 0.0f, {1.0f}, false, only_a0, {}, false});
    agent.Observe({{1.0f}, 0, 0.0f, {1.0f}, false, only_a0, {}, false});
    agent.Observe({{1.0f}, 1, 10.0f, {1.0f}, true, {}, {}, true});
  }
  return agent.QValues({-1.0f})[0];
}

TEST(DqnAgent, BootstrapMaximisesOnlyOverAllowedActions) {
  EXPECT_LT(LearnedValueBehindAMaskedAction(true), 1.0f);   // 0: the jackpot is out of reach
  EXPECT_GT(LearnedValueBehindAMaskedAction(false), 6.0f);  // gamma * 10 = 9 when allowed
}

// One state, two actions paying 0.86 and 0.87 forever: the 1 % gap of scenario A.
class NearlyFlatBandit : public Env {
 public:
  DiscreteSpace ActionSpace() const override { return {2}; }
  BoxSpace ObservationSpace() const override { return {{0}, {1}}; }
  std::vector<double> Reset(std::uint64_t) override {
    steps_ = 0;
    return {0.5};
  }
  StepResult Step(int action) override {
    StepResult r;
    r.observation = {0.5};
    r.reward = action == 1 ? 0.87 : 0.86;
    r.truncated = ++steps_ >= 100;
    return r;
  }
  const StepInfo& LastInfo() const override { return info_; }

 private:
  int steps_ = 0;
  StepInfo info_;
};

TEST(DqnAgent, NormalisedRewardsResolveAOnePercentGap) {
  NearlyFlatBandit env;
  const AgentSpec spec = SmallSpec(6, 20);
  DqnAgent agent(spec, 1, 2);
  Train(env, agent, spec, 1);
  const auto q = agent.QValues({0.0f});
  // Both actions lead to the same state, so the gap is the reward gap: 0.01 in raw units
  // (next to values of 8.6), about two standard deviations of the rewards seen here.
  EXPECT_NEAR(q[1] - q[0], 2.0f, 0.5f);
  EXPECT_EQ(agent.Act({0.0f}, {}, false), 1);
}

// The value of a state whose episodes only run out of time is bootstrapped through the cut;
// that of a terminal end is not (a bug here caps every value at an episode's rewards).
float LearnedValueOfOneStepEpisodes(bool truncate) {
  OneStepEnv env(truncate);
  AgentSpec spec = SmallSpec(8, 600);
  spec.normalise_rewards = false;  // a constant reward would standardise to 0
  spec.dqn.gamma = 0.5;
  spec.dqn.batch_size = 8;
  spec.dqn.warmup_steps = 8;
  spec.dqn.target_update_interval = 10;
  DqnAgent agent(spec, 1, 1);
  Train(env, agent, spec, 1);
  return agent.QValues({0.0f})[0];
}

TEST(DqnAgent, BootstrapsThroughTruncationNotThroughTermination) {
  EXPECT_NEAR(LearnedValueOfOneStepEpisodes(false), 1.0f, 0.05f);
  EXPECT_NEAR(LearnedValueOfOneStepEpisodes(true), 2.0f, 0.1f);  // 1 / (1 - 0.5)
}

TEST(DqnAgent, LearnsTheChain) {
  ChainEnv env;
  const AgentSpec spec = SmallSpec(3);
  DqnAgent agent(spec, 1, 2);
  const TrainResult result = Train(env, agent, spec, 1);
  // Greedy: straight to the end in 4 steps, from every state "right" is worth more.
  const EpisodeRecord& eval = result.curve.back();
  EXPECT_TRUE(eval.evaluation);
  EXPECT_EQ(eval.steps, 4);
  EXPECT_DOUBLE_EQ(result.final_info.positions[0].x, 4.0);
  const BoxSpace space = env.ObservationSpace();
  for (int s = 0; s < 4; ++s) {
    const auto q = agent.QValues(space.Normalise({static_cast<double>(s)}));
    EXPECT_GT(q[1], q[0]) << "state " << s;
  }
}

TEST(DqnAgent, SameSeedSamePolicyOtherSeedOther) {
  ExpectTheSeedDecidesThePolicy<DqnAgent, ChainEnv>(
      [](std::uint64_t seed) { return SmallSpec(seed, 5); }, 1, 2,
      [](const DqnAgent& agent) { return agent.QValues({0.25f}); });
}

std::vector<float> QValuesAtHalf(const DqnAgent& agent) {
  return agent.QValues({0.5f});
}

TEST(DqnAgent, SaveLoadRoundTrip) {
  ChainEnv env;
  const AgentSpec spec = SmallSpec(5, 5);
  DqnAgent trained(spec, 1, 2);
  Train(env, trained, spec, 1);
  DqnAgent loaded(SmallSpec(99), 1, 2);
  const auto dir = ExpectSaveLoadRoundTrip(trained, loaded, "rlpos-dqn-roundtrip", QValuesAtHalf,
                                           [&] { return DqnAgent(spec, 3, 2); });
  EXPECT_THROW(loaded.Load((dir / "missing").string()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(DqnAgent, RestoresTheKeptPolicyAfterLearningOn) {
  ChainEnv env;
  const AgentSpec spec = SmallSpec(5, 5);
  DqnAgent agent(spec, 1, 2);
  ExpectRestoresTheKeptPolicy(env, agent, spec, spec, QValuesAtHalf);
}

}  // namespace
}  // namespace rlpos
