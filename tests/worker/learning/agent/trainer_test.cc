// The trainer's checkpoints (agent.eval_interval): when they run, which policy they keep, and
// that the evaluation flies the kept one.
#include "worker/learning/agent_base/trainer.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "tests/worker/learning/agent/plain_training.h"
#include "tests/worker/learning/agent/tiny_envs.h"

namespace rlpos {
namespace {

// A scripted agent whose greedy policy after n training episodes is "right" (to the chain's
// end, reward 1) if n is in `good`, else "left" (never there). Its "networks" are n.
class ScriptedAgent : public Agent {
 public:
  explicit ScriptedAgent(std::set<int> good) : good_(std::move(good)) {}
  std::string Algorithm() const override { return "scripted"; }
  int Act(const std::vector<float>&, const ActionMask&, bool explore) override {
    return explore ? 0 : (good_.count(episodes_) ? 1 : 0);
  }
  std::optional<double> Observe(Transition t) override {
    if (t.episode_end)
      ++episodes_;
    return std::nullopt;
  }
  void KeepPolicy() override { kept_ = episodes_; }
  void RestoreKeptPolicy() override {
    if (kept_ < 0)
      throw std::logic_error("no policy kept to restore");
    episodes_ = kept_;
  }
  void Save(const std::string&) const override {}
  void Load(const std::string&) override {}

 private:
  std::set<int> good_;
  int episodes_ = 0;
  int kept_ = -1;
};

// An agent that always moves one way and records the end flags of what it is told.
class RecordingAgent : public Agent {
 public:
  explicit RecordingAgent(int action) : action_(action) {}
  std::string Algorithm() const override { return "recording"; }
  int Act(const std::vector<float>&, const ActionMask&, bool) override { return action_; }
  std::optional<double> Observe(Transition t) override {
    ends.emplace_back(t.terminal, t.episode_end);
    return std::nullopt;
  }
  void KeepPolicy() override {}
  void RestoreKeptPolicy() override {}
  void Save(const std::string&) const override {}
  void Load(const std::string&) override {}
  std::vector<std::pair<bool, bool>> ends;  // terminal, episode_end per transition

 private:
  int action_;
};

TEST(Trainer, TellsTheAgentTerminationFromTruncation) {
  ChainEnv env;  // the end (state 4) terminates; 20 steps truncate
  RecordingAgent right(1);
  RunEpisode(env, right, 1, true);
  ASSERT_EQ(right.ends.size(), 4u);
  EXPECT_EQ(right.ends.back(), std::make_pair(true, true));  // no bootstrap from a terminal state
  RecordingAgent left(0);
  RunEpisode(env, left, 1, true);
  ASSERT_EQ(left.ends.size(), 20u);
  EXPECT_EQ(left.ends.back(), std::make_pair(false, true));  // cut short: bootstrap, but end
  for (std::size_t i = 0; i + 1 < left.ends.size(); ++i)
    EXPECT_EQ(left.ends[i], std::make_pair(false, false)) << "step " << i + 1;
}

AgentSpec Spec(int train_episodes, int eval_interval) {
  AgentSpec spec = PlainTrainingSpec("dqn", 1, train_episodes);
  spec.eval_interval = eval_interval;
  return spec;
}

// agent.improvement_reward: each step learns its rise above the episode's best so far, so the
// episode's learnt rewards sum to its best minus its start; without it, the env's reward.
TEST(LearntReward, TheRisesAboveTheEpisodesBestSumToItsBestMinusItsStart) {
  AgentSpec spec = Spec(1, 0);
  const std::vector<double> rewards = {0.4, 0.6, 0.55, 0.7, 0.7, 0.2};
  const std::vector<double> rises = {0.0, 0.1, 0.0, 0.1, 0.0, 0.0};
  spec.improvement_reward = true;
  double best = 0.5;  // the start state's
  double sum = 0.0;
  for (std::size_t t = 0; t < rewards.size(); ++t) {
    const double learnt = LearntReward(spec, rewards[t], best);
    EXPECT_NEAR(learnt, rises[t], 1e-12) << "step " << t + 1;
    sum += learnt;
  }
  EXPECT_DOUBLE_EQ(best, 0.7);
  EXPECT_NEAR(sum, 0.7 - 0.5, 1e-12);
  spec.improvement_reward = false;
  best = 0.5;
  for (double r : rewards)
    EXPECT_EQ(LearntReward(spec, r, best), r);
  EXPECT_DOUBLE_EQ(best, 0.7);  // kept either way
}

// Per-scenario training cannot measure a step against its episode's start, so it refuses the
// key rather than learn something else under its name.
TEST(Trainer, RefusesTheImprovementRewardPerScenario) {
  ChainEnv env;
  ScriptedAgent agent({});
  AgentSpec spec = Spec(2, 0);
  spec.improvement_reward = true;
  try {
    Train(env, agent, spec, 1);
    FAIL() << "trained with agent.improvement_reward";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("agent.improvement_reward"), std::string::npos)
        << e.what();
  }
}

TEST(Trainer, WithoutCheckpointsTheLastPolicyAnswers) {
  ChainEnv env;
  ScriptedAgent agent({2});
  const TrainResult r = Train(env, agent, Spec(5, 0), 1);
  ASSERT_EQ(r.curve.size(), 6u);
  for (const auto& e : r.curve)
    EXPECT_FALSE(e.checkpoint);
  EXPECT_EQ(r.policy_episode, 5);
  EXPECT_DOUBLE_EQ(r.final_info.positions[0].x, 0.0);  // the last policy goes left
}

TEST(Trainer, CheckpointsEveryIntervalAndAfterTheLastThenTheBestIsEvaluated) {
  ChainEnv env;
  ScriptedAgent agent({2});  // good after episode 2 only
  std::vector<std::string> seen;
  const TrainResult r = Train(env, agent, Spec(5, 2), 1, [&](const EpisodeRecord& e) {
    seen.push_back(std::to_string(e.episode) + (e.checkpoint ? "c" : e.evaluation ? "e" : "t"));
  });
  EXPECT_EQ(seen, (std::vector<std::string>{"1t", "2t", "2c", "3t", "4t", "4c", "5t", "5c", "6e"}));
  ASSERT_EQ(r.curve.size(), seen.size());
  EXPECT_TRUE(r.curve[2].evaluation);
  EXPECT_DOUBLE_EQ(r.curve[2].final_reward, 1.0);
  EXPECT_DOUBLE_EQ(r.curve[5].final_reward, 0.0);
  EXPECT_EQ(r.policy_episode, 2);
  EXPECT_DOUBLE_EQ(r.final_info.positions[0].x, 4.0);  // the kept policy flies to the end
  EXPECT_DOUBLE_EQ(r.final_reward, 1.0);
}

TEST(Trainer, OfEqualCheckpointsTheLatestIsKept) {
  ChainEnv env;
  ScriptedAgent agent({2, 4});
  const TrainResult r = Train(env, agent, Spec(5, 2), 1);
  EXPECT_EQ(r.policy_episode, 4);
  EXPECT_DOUBLE_EQ(r.final_reward, 1.0);
}

TEST(Trainer, EarlyStoppingEndsTrainingAfterCheckpointsThatDoNotBeatTheKeptOne) {
  ChainEnv env;
  ScriptedAgent agent({2, 4});  // good after 2 (kept), equal after 4: not an improvement
  AgentSpec spec = Spec(20, 2);
  spec.early_stop_checkpoints = 2;
  std::vector<std::string> seen;
  const TrainResult r = Train(env, agent, spec, 1, [&](const EpisodeRecord& e) {
    seen.push_back(std::to_string(e.episode) + (e.checkpoint ? "c" : e.evaluation ? "e" : "t"));
  });
  // Checkpoints 4 and 6 do not beat 2's reward: stop after 6; the evaluation keeps its seed.
  EXPECT_EQ(seen, (std::vector<std::string>{"1t", "2t", "2c", "3t", "4t", "4c", "5t", "6t", "6c",
                                            "21e"}));
  EXPECT_EQ(r.episodes_trained, 6);
  EXPECT_EQ(r.policy_episode, 4);  // of equals, the latest
  EXPECT_DOUBLE_EQ(r.final_reward, 1.0);
}

TEST(Trainer, WithoutEarlyStoppingEveryEpisodeTrains) {
  ChainEnv env;
  ScriptedAgent agent({2});
  const TrainResult r = Train(env, agent, Spec(9, 2), 1);
  EXPECT_EQ(r.episodes_trained, 9);
  EXPECT_EQ(r.policy_episode, 2);
}

// The chain, recording the reset options of every episode.
class OptionsChainEnv : public ChainEnv {
 public:
  using ChainEnv::Reset;
  std::vector<double> Reset(std::uint64_t seed, const ResetOptions& options) override {
    random_starts.push_back(options.random_start);
    return Reset(seed);
  }
  std::vector<bool> random_starts;
};

TEST(Trainer, ExploringStartsAndTheStepLimitShapeTrainingEpisodesOnly) {
  OptionsChainEnv env;
  RecordingAgent left(0);  // never reaches the end: every episode runs to its limit
  AgentSpec spec = Spec(3, 1);
  spec.exploring_starts = true;
  spec.train_episode_steps = 5;
  const TrainResult r = Train(env, left, spec, 1);
  // Training, checkpoint, ... evaluation: only training episodes start at random.
  EXPECT_EQ(env.random_starts, (std::vector<bool>{true, false, true, false, true, false, false}));
  ASSERT_EQ(r.curve.size(), 7u);
  for (const EpisodeRecord& e : r.curve)
    EXPECT_EQ(e.steps, e.evaluation ? 20 : 5) << "episode " << e.episode;
  // A step limit truncates: the last transition ends the episode but still bootstraps.
  ASSERT_EQ(left.ends.size(), 15u);
  for (std::size_t i = 0; i < left.ends.size(); ++i)
    EXPECT_EQ(left.ends[i], std::make_pair(false, i % 5 == 4)) << "transition " << i;
}

TEST(Trainer, EveryNthTrainingEpisodeStartsFromTheBaseline) {
  OptionsChainEnv env;
  RecordingAgent left(0);
  AgentSpec spec = Spec(6, 0);
  spec.exploring_starts = true;
  spec.baseline_start_every = 3;
  Train(env, left, spec, 1);
  // Training episodes 3 and 6 start where the evaluation does; the evaluation never at random.
  EXPECT_EQ(env.random_starts, (std::vector<bool>{true, true, false, true, true, false, false}));
}

TEST(Trainer, WithoutTheOptionsEpisodesAreTheEnvs) {
  OptionsChainEnv env;
  RecordingAgent left(0);
  const TrainResult r = Train(env, left, Spec(2, 0), 1);
  EXPECT_EQ(env.random_starts, (std::vector<bool>{false, false, false}));
  for (const EpisodeRecord& e : r.curve)
    EXPECT_EQ(e.steps, 20);
}

}  // namespace
}  // namespace rlpos
