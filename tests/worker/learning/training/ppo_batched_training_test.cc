// PPO collecting its rollouts from several analytic envs of scenario B at once.
#include "worker/learning/training/ppo_batched_training.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "common/config/config_error.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/make_agent.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;

// A short training: 24 episodes of 10 steps from random starts (every 4th from the baseline),
// rollouts of 10 steps per env, a checkpoint every 8 episodes, a 20-step evaluation.
Scenario ShortB(int num_envs) {
  return LoadScenario(
      std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json",
      {"env.fidelity=analytic", "env.episode_duration=2", "agent.algorithm=ppo",
       "agent.train_episodes=24", "agent.train_episode_steps=10", "agent.baseline_start_every=4",
       "agent.eval_interval=8", "agent.ppo.rollout_steps=10", "agent.ppo.epochs=2",
       "agent.ppo.num_envs=" + std::to_string(num_envs)});
}

std::string Bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Trained {
  TrainResult result;
  std::string policy;  // policy.pt's bytes
  std::string value;   // value.pt's
};

Trained Save(PpoAgent& agent, TrainResult result, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rlpos-ppo-batched-" + name);
  fs::remove_all(dir);
  agent.Save(dir.string());
  Trained t{std::move(result), Bytes(dir / "policy.pt"), Bytes(dir / "value.pt")};
  fs::remove_all(dir);
  EXPECT_FALSE(t.policy.empty());
  return t;
}

std::unique_ptr<PpoAgent> MakePpo(const Scenario& s) {
  UavPositioningEnv env(s);
  const std::int64_t steps = std::int64_t{s.agent.train_episodes} * s.agent.train_episode_steps;
  return std::unique_ptr<PpoAgent>(
      dynamic_cast<PpoAgent*>(MakeAgent(s.agent, env, steps).release()));
}

Trained Batched(const Scenario& s, std::size_t threads) {
  const std::unique_ptr<PpoAgent> agent = MakePpo(s);
  TrainResult r = TrainPpoBatched(s, *agent, 7000001, threads);
  return Save(*agent, std::move(r),
              "n" + std::to_string(s.agent.ppo.num_envs) + "-t" + std::to_string(threads));
}

Trained Single(const Scenario& s) {
  const std::unique_ptr<PpoAgent> agent = MakePpo(s);
  UavPositioningEnv env(s);
  TrainResult r = Train(env, *agent, s.agent, 7000001);
  return Save(*agent, std::move(r), "single");
}

void ExpectSameCurve(const TrainResult& a, const TrainResult& b) {
  ASSERT_EQ(a.curve.size(), b.curve.size());
  for (std::size_t i = 0; i < a.curve.size(); ++i) {
    EXPECT_EQ(a.curve[i].episode, b.curve[i].episode) << "record " << i;
    EXPECT_EQ(a.curve[i].checkpoint, b.curve[i].checkpoint) << "record " << i;
    EXPECT_EQ(a.curve[i].steps, b.curve[i].steps) << "record " << i;
    EXPECT_EQ(a.curve[i].total_reward, b.curve[i].total_reward) << "record " << i;
    EXPECT_EQ(a.curve[i].updates, b.curve[i].updates) << "record " << i;
    EXPECT_EQ(a.curve[i].mean_loss, b.curve[i].mean_loss) << "record " << i;
    const Vec3& p = a.curve[i].final_info.positions.front();
    const Vec3& q = b.curve[i].final_info.positions.front();
    EXPECT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z) << "record " << i;
  }
  EXPECT_EQ(a.policy_episode, b.policy_episode);
  EXPECT_EQ(a.final_reward, b.final_reward);
}

// With one env the batched collection is today's training, transition for transition.
TEST(PpoBatchedTraining, OneEnvGivesTrainsPolicyBytes) {
  const Scenario s = ShortB(1);
  const Trained single = Single(s);
  const Trained batched = Batched(s, 1);
  ExpectSameCurve(single.result, batched.result);
  EXPECT_EQ(single.policy, batched.policy);
  EXPECT_EQ(single.value, batched.value);
}

// The envs are independent values: the thread count that steps them changes no byte.
TEST(PpoBatchedTraining, SamePolicyBytesWhateverTheThreadCount) {
  const Scenario s = ShortB(4);
  const Trained one = Batched(s, 1);
  const Trained two = Batched(s, 2);
  const Trained three = Batched(s, 3);
  ExpectSameCurve(one.result, two.result);
  ExpectSameCurve(one.result, three.result);
  EXPECT_EQ(one.policy, two.policy);
  EXPECT_EQ(one.policy, three.policy);
  EXPECT_EQ(one.value, three.value);
  // Four envs collect other rollouts than one does: another seed stream, another policy.
  EXPECT_NE(one.policy, Batched(ShortB(1), 1).policy);
}

// Rounds of 4: every training episode is recorded once, in order; checkpoints follow the
// rounds in which episodes 8, 16 and 24 fall.
TEST(PpoBatchedTraining, RecordsEveryEpisodeAndTheCheckpoints) {
  const Trained t = Batched(ShortB(4), 2);
  std::vector<int> train, checkpoints;
  int updates = 0;
  for (const EpisodeRecord& r : t.result.curve) {
    if (r.checkpoint)
      checkpoints.push_back(r.episode);
    else if (!r.evaluation)
      train.push_back(r.episode);
    if (!r.evaluation) {
      EXPECT_EQ(r.steps, 10) << "episode " << r.episode;
      updates += r.updates;
    }
  }
  ASSERT_EQ(train.size(), 24u);
  for (int e = 0; e < 24; ++e)
    EXPECT_EQ(train[static_cast<std::size_t>(e)], e + 1);
  EXPECT_EQ(checkpoints, (std::vector<int>{8, 16, 24}));
  EXPECT_EQ(updates, 24 * 10 / (10 * 4));  // each of 10 steps from each of the 4 envs
  EXPECT_EQ(t.result.episodes_trained, 24);
}

std::string ErrorOf(const std::vector<std::string>& overrides) {
  try {
    LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json", overrides);
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "no error";
}

TEST(PpoBatchedTraining, RefusesBadNumEnvsInOneLine) {
  EXPECT_EQ(ErrorOf({"agent.ppo.num_envs=0"}),
            "--set agent.ppo.num_envs=0: /agent/ppo/num_envs: must be in [1, 4096], got 0");
  EXPECT_EQ(ErrorOf({"agent.ppo.num_envs=5000"}),
            "--set agent.ppo.num_envs=5000: /agent/ppo/num_envs: must be in [1, 4096], got 5000");
  const std::string fraction = ErrorOf({"agent.ppo.num_envs=2.5"});
  EXPECT_EQ(fraction.find('\n'), std::string::npos);
  EXPECT_NE(fraction.find("/agent/ppo/num_envs: "), std::string::npos) << fraction;
}

}  // namespace
}  // namespace rlpos
