// PPO across generated scenarios: seeded (the same policy twice, whatever the thread count),
// within its budget, and keeping the policy it scored best.
#include "worker/learning/training/generalist_training.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent_base/greedy_flight.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {
namespace {

// A placement's coordinates, UAV by UAV, to compare bit for bit.
std::vector<double> Coordinates(const Placement& placement) {
  std::vector<double> xyz;
  for (const Vec3& at : placement)
    xyz.insert(xyz.end(), {at.x, at.y, at.z});
  return xyz;
}

namespace fs = std::filesystem;

// Tiny: 4 envs of 10-step episodes, rollouts of 10 steps per env, a 20-step validation flight.
Scenario Settings() {
  Scenario s;
  s.env.fidelity = "analytic";
  s.env.observations = {"zone", "ues", "heights"};
  s.env.observed_ues = 4;
  s.env.height_map = 3;
  s.env.episode_duration = 2;
  s.agent.algorithm = "ppo";
  s.agent.hidden = {16};
  s.agent.seed = 5;
  s.agent.train_episode_steps = 10;
  s.agent.ppo.num_envs = 4;
  s.agent.ppo.rollout_steps = 10;
  s.agent.ppo.epochs = 2;
  return s;
}

// How the UAVs of a tiny training move and what its critic sees.
struct Team {
  int uavs = 1;                     // the draw's UAVs: 1, or 2-uavs
  bool joint = false;               // agent.joint_steps
  bool centralised_critic = false;  // agent.ppo.centralised_critic
  bool best = false;                // the "best" observation
  bool improvement = false;         // agent.improvement_reward
};

ScenarioDraw Draw(const Team& team = {}) {
  Scenario settings = Settings();
  if (team.uavs > 1)
    settings.env.observations.push_back("others");
  settings.agent.joint_steps = team.joint;
  settings.agent.ppo.centralised_critic = team.centralised_critic;
  if (team.best)
    settings.env.observations.push_back("best");
  settings.agent.improvement_reward = team.improvement;
  const int low = team.uavs > 1 ? 2 : 1;
  return ScenarioDraw(
      {{GeneratorStyle::kUrban, GeneratorStyle::kSuburb}, {low, team.uavs}, CountRange{4, 6}},
      settings, 5);
}

struct Trained {
  GeneralistResult result;
  std::string policy;  // policy.pt's bytes
  std::string value;   // value.pt's
};

Trained TrainTiny(std::size_t threads, std::int64_t steps = 200, const Team& team = {}) {
  const ScenarioDraw draw = Draw(team);
  const Scenario example = draw.Validation(0).scenario;
  UavPositioningEnv env(example);
  PpoAgent agent(example.agent, static_cast<int>(env.ObservationSpace().Dim()), env.ActionSpace().n,
                 steps);
  GeneralistOptions options;
  options.steps = steps;
  options.validation_scenarios = 2;
  options.validation_every = 80;
  options.threads = threads;
  Trained t{TrainGeneralist(draw, agent, example.agent, options, 5000001), "", ""};
  const fs::path dir =
      fs::temp_directory_path() / ("rlpos-generalist-" + std::to_string(::getpid()) + "-" +
                                   std::to_string(threads) + "-" + std::to_string(steps));
  fs::remove_all(dir);
  agent.Save(dir.string());
  const auto read = [&](const char* name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  t.policy = read("policy.pt");
  t.value = read("value.pt");
  fs::remove_all(dir);
  return t;
}

TEST(GeneralistTraining, SpendsItsBudgetInWholeRoundsOfFreshScenarios) {
  const Trained t = TrainTiny(1);
  // Rounds of 4 episodes of 10 steps: 200 steps are 5 rounds.
  EXPECT_EQ(t.result.steps, 200);
  EXPECT_EQ(t.result.episodes, 20);
  EXPECT_EQ(t.result.first_draw, 0u);
  EXPECT_EQ(t.result.last_draw, 19u);
  ASSERT_EQ(t.result.validation.size(), 2u);
  // The kept policy's score is the mean of its flights' rewards over the oracle's.
  for (const ValidationScore& v : t.result.validation) {
    EXPECT_GT(v.oracle_reward, 0.0) << v.origin;
    EXPECT_LE(v.final_reward, v.oracle_reward + 1e-12) << v.origin;  // nothing beats the oracle
    EXPECT_DOUBLE_EQ(v.ratio, v.final_reward / v.oracle_reward) << v.origin;
  }
  EXPECT_DOUBLE_EQ(t.result.best_validation,
                   (t.result.validation[0].ratio + t.result.validation[1].ratio) / 2);
  EXPECT_GT(t.result.kept_at_steps, 0);
  EXPECT_FALSE(t.policy.empty());
}

TEST(GeneralistTraining, TheSameSeedGivesTheSamePolicyOnAnyThreadCount) {
  const Trained one = TrainTiny(1);
  const Trained two = TrainTiny(2);
  EXPECT_EQ(one.policy, two.policy);
  EXPECT_EQ(one.result.best_validation, two.result.best_validation);
  EXPECT_EQ(one.result.kept_at_steps, two.result.kept_at_steps);
  // A longer budget trains on: another policy.
  EXPECT_NE(TrainTiny(1, 280).policy, one.policy);
}

// Several UAVs moving at once (agent.joint_steps): a row per UAV and step, each its own stream;
// seeded on any thread count; the centralised critic's team state changes what is learnt.
TEST(GeneralistTraining, JointStepsWithACentralisedCriticAreSeededAndLearnFromTheTeamState) {
  const Team mappo{3, true, true};
  const Trained one = TrainTiny(1, 240, mappo);
  const Trained two = TrainTiny(2, 240, mappo);
  EXPECT_EQ(one.policy, two.policy);
  EXPECT_EQ(one.value, two.value);
  EXPECT_EQ(one.result.best_validation, two.result.best_validation);
  // Rounds of 4 episodes of 10 joint steps, each of 2 or 3 rows: at least 80 rows a round, so
  // fewer episodes than the 24 that 240 steps in turns take.
  EXPECT_GE(one.result.steps, 240);
  EXPECT_LT(one.result.episodes, 24);
  EXPECT_EQ(one.result.episodes % 4, 0);
  ASSERT_EQ(one.result.validation.size(), 2u);
  for (const ValidationScore& v : one.result.validation)
    EXPECT_LE(v.final_reward, v.oracle_reward + 1e-12) << v.origin;
  // The same training with a critic of the UAV's own observation learns another policy (the
  // team state reaches the advantages), and the same value network shape only without it.
  const Trained own = TrainTiny(1, 240, {3, true, false});
  EXPECT_NE(own.policy, one.policy);
  EXPECT_NE(own.value.size(), one.value.size());
  // Turns instead of joint steps: another policy again.
  EXPECT_NE(TrainTiny(1, 240, {3, false, true}).policy, one.policy);
}

// agent.improvement_reward (with the "best" observation): seeded on any thread count, and what is
// learnt is not the env's reward (the same observations without it learn another policy).
TEST(GeneralistTraining, TheImprovementRewardIsSeededAndChangesWhatIsLearnt) {
  const Team improving{3, false, false, true, true};
  const Trained one = TrainTiny(1, 240, improving);
  const Trained two = TrainTiny(2, 240, improving);
  EXPECT_EQ(one.policy, two.policy);
  EXPECT_EQ(one.value, two.value);
  EXPECT_EQ(one.result.best_validation, two.result.best_validation);
  // The same observations (and network sizes) learning the env's reward: another policy.
  Team level = improving;
  level.improvement = false;
  const Trained plain = TrainTiny(1, 240, level);
  EXPECT_EQ(plain.policy.size(), one.policy.size());
  EXPECT_FALSE(plain.policy == one.policy) << "the env's reward learnt the same policy";
}

// A greedy flight in the analytic env, read off its cycle (placements, what the UEs get, the
// reward) ends bit for bit where the whole flight ends: with one UAV, with three in turns and
// with three moving at once.
TEST(GreedyFlightInTheEnv, EndsWhereTheWholeFlightEndsWithOneUavAndWithThree) {
  for (const Team team : {Team{1}, Team{3}, Team{3, true}}) {
    const int uavs = team.uavs;
    Scenario settings = Settings();
    settings.env.episode_duration = 30;  // 300 steps
    settings.agent.joint_steps = team.joint;
    if (uavs > 1)
      settings.env.observations.push_back("others");
    const ScenarioDraw draw(
        {{GeneratorStyle::kUrban, GeneratorStyle::kSuburb}, {uavs, uavs}, CountRange{4, 6}},
        settings, 7);
    int shortened = 0;
    for (int i = 0; i < 4; ++i) {
      const Scenario s = draw.Validation(static_cast<std::uint64_t>(i)).scenario;
      const std::string where = std::to_string(uavs) + " UAV(s)" + (team.joint ? " at once" : "") +
                                ", validation " + std::to_string(i);
      UavPositioningEnv env(s);
      PpoAgent agent(s.agent, static_cast<int>(env.ObservationSpace().Dim()),
                     env.ActionSpace().n);  // untrained: its seeded first weights
      const EpisodeOptions greedy = GreedyEpisodeOptions(s.agent);
      const EpisodeRecord whole = RunEpisode(env, agent, 1, false, nullptr, greedy);
      const GreedyFlight flight = FlyGreedy(env, agent, 1, greedy);
      ASSERT_EQ(whole.steps, 300) << where;
      EXPECT_EQ(flight.steps, whole.steps) << where;
      EXPECT_EQ(Coordinates(flight.final_info.positions), Coordinates(whole.final_info.positions))
          << where;
      EXPECT_EQ(flight.final_info.active_uav, whole.final_info.active_uav) << where;
      EXPECT_EQ(flight.final_info.serving, whole.final_info.serving) << where;
      EXPECT_EQ(flight.final_info.snr_db, whole.final_info.snr_db) << where;
      EXPECT_EQ(flight.final_info.throughput_mbps, whole.final_info.throughput_mbps) << where;
      EXPECT_EQ(flight.final_reward, whole.final_reward) << where;
      shortened += flight.steps_flown < flight.steps ? 1 : 0;
    }
    EXPECT_GT(shortened, 0) << uavs << " UAV(s)";
  }
}

TEST(GeneralistTraining, RefusesAnEmptyBudget) {
  const ScenarioDraw draw = Draw();
  const Scenario example = draw.Validation(0).scenario;
  UavPositioningEnv env(example);
  PpoAgent agent(example.agent, static_cast<int>(env.ObservationSpace().Dim()),
                 env.ActionSpace().n);
  EXPECT_THROW(TrainGeneralist(draw, agent, example.agent, GeneralistOptions{}, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
