// The PPO agent on tiny known envs: it learns, it is seeded, it saves and loads, it obeys masks.
#include "worker/learning/agent/ppo_agent.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/worker/learning/agent/plain_training.h"
#include "tests/worker/learning/agent/policy_checks.h"
#include "tests/worker/learning/agent/tiny_envs.h"
#include "worker/env/gym/team_state.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {
namespace {

AgentSpec PpoSpecFor(std::uint64_t seed, int episodes) {
  AgentSpec spec = PlainTrainingSpec("ppo", seed, episodes);
  spec.ppo.learning_rate = 3e-3;
  spec.ppo.rollout_steps = 64;
  return spec;
}

TEST(PpoAgent, DefaultsAreTheReferenceSetTunedForTenEpisodes) {
  const PpoSpec ppo;
  EXPECT_DOUBLE_EQ(ppo.gae_lambda, 0.95);
  EXPECT_DOUBLE_EQ(ppo.clip, 0.2);
  EXPECT_DOUBLE_EQ(ppo.entropy_coefficient, 0.01);
  EXPECT_DOUBLE_EQ(ppo.value_coefficient, 0.5);
  EXPECT_DOUBLE_EQ(ppo.max_grad_norm, 0.5);
  // Tuned (docs/agents.md, PPO and SAC): the reference 2.5e-4, 0.99, 128 and 4 epochs learn nothing
  // in 10k steps.
  EXPECT_DOUBLE_EQ(ppo.learning_rate, 1e-3);
  EXPECT_DOUBLE_EQ(ppo.gamma, 0.9);
  EXPECT_EQ(ppo.rollout_steps, 256);
  EXPECT_EQ(ppo.epochs, 10);
}

TEST(PpoAgent, LearnsTheChain) {
  ChainEnv env;
  const AgentSpec spec = PpoSpecFor(3, 60);
  PpoAgent agent(spec, 1, 2);
  const TrainResult result = Train(env, agent, spec, 1);
  const EpisodeRecord& eval = result.curve.back();
  EXPECT_TRUE(eval.evaluation);
  EXPECT_EQ(eval.steps, 4);  // greedy: straight to the end
  const BoxSpace space = env.ObservationSpace();
  for (int s = 0; s < 4; ++s) {
    const auto p = agent.Probabilities(space.Normalise({static_cast<double>(s)}), {});
    EXPECT_GT(p[1], 0.5f) << "state " << s;
  }
  int updates = 0;
  for (const auto& r : result.curve)
    updates += r.updates;
  EXPECT_GT(updates, 0);
}

TEST(PpoAgent, SameSeedSamePolicyOtherSeedOther) {
  ExpectTheSeedDecidesThePolicy<PpoAgent, ChainEnv>(
      [](std::uint64_t seed) { return PpoSpecFor(seed, 8); }, 1, 2,
      [](const PpoAgent& agent) { return agent.Probabilities({0.25f}, {}); });
}

TEST(PpoAgent, NeverTakesAMaskedAction) {
  PpoAgent agent(PpoSpecFor(1, 1), 1, 3);
  const ActionMask no_middle{1, 0, 1};
  for (int i = 0; i < 300; ++i) {
    EXPECT_NE(agent.Act({0.0f}, no_middle, true), 1);
    agent.Observe({{0.0f}, 0, 0.0f, {0.0f}, false, no_middle, {}, false});
  }
  EXPECT_EQ(agent.Probabilities({0.0f}, no_middle)[1], 0.0f);
  EXPECT_NE(agent.Act({0.0f}, ActionMask{0, 1, 0}, false), 0);
  EXPECT_THROW(agent.Act({0.0f}, ActionMask{0, 0, 0}, false), std::invalid_argument);
}

TEST(PpoAgent, LearnsOncePerRollout) {
  AgentSpec spec = PpoSpecFor(1, 1);
  spec.ppo.rollout_steps = 16;
  PpoAgent agent(spec, 1, 2);
  for (int i = 1; i <= 32; ++i) {
    const int a = agent.Act({0.0f}, {}, true);
    const auto loss = agent.Observe({{0.0f}, a, 1.0f, {0.0f}, false, {}, {}, i % 8 == 0});
    EXPECT_EQ(loss.has_value(), i % 16 == 0) << "step " << i;
  }
}

// Four rollouts planned: they learn at 1, 3/4, 1/2 and 1/4 of the rate; without annealing, or
// without a known training length, at the full rate.
TEST(PpoAgent, AnnealsTheLearningRateOverThePlannedRollouts) {
  const auto rates = [](bool anneal, std::int64_t training_steps) {
    AgentSpec spec = PpoSpecFor(1, 1);
    spec.ppo.rollout_steps = 16;
    spec.ppo.anneal_learning_rate = anneal;
    PpoAgent agent(spec, 1, 2, training_steps);
    std::vector<double> seen;
    for (int i = 1; i <= 64; ++i) {
      const int a = agent.Act({0.0f}, {}, true);
      if (agent.Observe({{0.0f}, a, 1.0f, {0.0f}, false, {}, {}, i % 8 == 0}))
        seen.push_back(agent.LearningRate() / spec.ppo.learning_rate);
    }
    return seen;
  };
  const std::vector<double> annealed = rates(true, 64);
  ASSERT_EQ(annealed.size(), 4u);
  EXPECT_DOUBLE_EQ(annealed[0], 1.0);
  EXPECT_DOUBLE_EQ(annealed[1], 0.75);
  EXPECT_DOUBLE_EQ(annealed[2], 0.5);
  EXPECT_DOUBLE_EQ(annealed[3], 0.25);
  EXPECT_EQ(rates(false, 64), std::vector<double>(4, 1.0));
  EXPECT_EQ(rates(true, 0), std::vector<double>(4, 1.0));
}

std::vector<float> ProbabilitiesAtHalf(const PpoAgent& agent) {
  return agent.Probabilities({0.5f}, {});
}

TEST(PpoAgent, SaveLoadRoundTrip) {
  ChainEnv env;
  const AgentSpec spec = PpoSpecFor(5, 5);
  PpoAgent trained(spec, 1, 2);
  Train(env, trained, spec, 1);
  PpoAgent loaded(PpoSpecFor(99, 5), 1, 2);
  const auto dir =
      ExpectSaveLoadRoundTrip(trained, loaded, "rlpos-ppo-roundtrip", ProbabilitiesAtHalf,
                              [&] { return PpoAgent(spec, 3, 2); });
  // A campaign's artifacts carry policy.pt, not the critic: acting needs only the actor.
  ASSERT_TRUE(std::filesystem::remove(dir / "value.pt"));
  PpoAgent actor_only(PpoSpecFor(99, 5), 1, 2);
  actor_only.Load(dir.string());
  EXPECT_EQ(actor_only.Probabilities({0.5f}, {}), trained.Probabilities({0.5f}, {}));
  std::filesystem::remove_all(dir);
}

TEST(PpoAgent, RestoresTheKeptPolicyAfterLearningOn) {
  ChainEnv env;
  const AgentSpec spec = PpoSpecFor(5, 5);
  PpoAgent agent(spec, 1, 2);
  // Learning on for 30 episodes: enough steps for several rollouts.
  ExpectRestoresTheKeptPolicy(env, agent, spec, PpoSpecFor(5, 30), ProbabilitiesAtHalf);
}

// Acts and learns on the chain for `steps` steps from where `env` stands; the actions taken.
std::vector<int> Drive(ChainEnv& env, PpoAgent& agent, int steps) {
  const BoxSpace space = env.ObservationSpace();
  std::vector<int> actions;
  std::vector<float> observation = space.Normalise({static_cast<double>(
      env.LastInfo().positions.empty() ? 0.0 : env.LastInfo().positions[0].x)});
  for (int k = 0; k < steps; ++k) {
    const int action = agent.Act(observation, {}, true);
    const StepResult r = env.Step(action);
    Transition t;
    t.observation = observation;
    t.action = action;
    t.reward = static_cast<float>(r.reward);
    t.next_observation = space.Normalise(r.observation);
    t.terminal = r.terminated;
    t.episode_end = r.terminated || r.truncated;
    agent.Observe(t);
    actions.push_back(action);
    observation = t.episode_end ? space.Normalise(env.Reset(0)) : t.next_observation;
  }
  return actions;
}

TEST(PpoAgent, ATrainingStateResumesExactlyWhereItWasSaved) {
  const AgentSpec spec = PpoSpecFor(5, 5);  // rollouts of 64 steps
  const auto file = std::filesystem::temp_directory_path() / "rlpos-ppo-state";
  ChainEnv env_a;
  env_a.Reset(0);
  PpoAgent a(spec, 1, 2, 640);
  Drive(env_a, a, 100);
  EXPECT_FALSE(a.AtRolloutStart());
  EXPECT_THROW(a.SaveTrainingState(file.string()), std::logic_error);
  Drive(env_a, a, 28);  // 128: two rollouts learnt, none begun
  ASSERT_TRUE(a.AtRolloutStart());
  a.KeepPolicy();
  a.SaveTrainingState(file.string());

  // Another seed's agent, given the state, goes on as the first does.
  ChainEnv env_b = env_a;
  PpoAgent b(PpoSpecFor(99, 5), 1, 2, 640);
  b.LoadTrainingState(file.string());
  EXPECT_EQ(Drive(env_b, b, 300), Drive(env_a, a, 300));
  EXPECT_EQ(b.Probabilities({0.5f}, {}), a.Probabilities({0.5f}, {}));
  EXPECT_EQ(b.LearningRate(), a.LearningRate());
  a.RestoreKeptPolicy();
  b.RestoreKeptPolicy();
  EXPECT_EQ(b.Probabilities({0.5f}, {}), a.Probabilities({0.5f}, {}));

  // Another shape, or a damaged file: a runtime_error that names the file.
  PpoAgent wider(spec, 3, 2);
  try {
    wider.LoadTrainingState(file.string());
    ADD_FAILURE() << "loaded the state of another shape";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": "), std::string::npos) << e.what();
  }
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 5);
  EXPECT_THROW(b.LoadTrainingState(file.string()), std::runtime_error);
  std::filesystem::remove(file);
  EXPECT_THROW(b.LoadTrainingState(file.string()), std::runtime_error);
}

// agent.ppo.centralised_critic: every transition carries the acting agent's team state, which
// reaches what is learnt (through the critic's advantages); a transition without one, or one for
// a critic without it, is refused; the training state keeps the wider critic.
TEST(PpoAgent, ACentralisedCriticLearnsFromEachTransitionsTeamState) {
  AgentSpec spec = PpoSpecFor(3, 1);
  spec.ppo.rollout_steps = 16;
  spec.ppo.centralised_critic = true;
  // The same observations, actions and rewards; the team states differ by `shift`.
  const auto train = [&](float shift) {
    PpoAgent agent(spec, 1, 2);
    EXPECT_TRUE(agent.NeedsTeamState());
    for (int i = 1; i <= 16; ++i) {
      const int a = agent.Act({0.0f}, {}, true);
      Transition t{{0.0f}, a, static_cast<float>(a), {0.0f}, false, {}, {}, i % 8 == 0};
      t.team_state.assign(kTeamStateWidth, 0.0f);
      t.next_team_state.assign(kTeamStateWidth, 0.0f);
      t.team_state[0] = static_cast<float>(i % 4) / 4.0f + shift;
      t.next_team_state[0] = static_cast<float>((i + 1) % 4) / 4.0f + shift;
      agent.Observe(std::move(t));
    }
    return agent.Probabilities({0.0f}, {});
  };
  EXPECT_EQ(train(0.0f), train(0.0f));
  EXPECT_NE(train(0.5f), train(0.0f));

  PpoAgent agent(spec, 1, 2);
  const int a = agent.Act({0.0f}, {}, true);
  EXPECT_THROW(agent.Observe({{0.0f}, a, 1.0f, {0.0f}, false, {}, {}, false}),
               std::invalid_argument);
  AgentSpec own = spec;
  own.ppo.centralised_critic = false;
  PpoAgent plain(own, 1, 2);
  EXPECT_FALSE(plain.NeedsTeamState());
  Transition with_team{{0.0f}, plain.Act({0.0f}, {}, true), 1.0f, {0.0f}, false, {}, {}, false};
  with_team.team_state.assign(kTeamStateWidth, 0.0f);
  with_team.next_team_state.assign(kTeamStateWidth, 0.0f);
  EXPECT_THROW(plain.Observe(with_team), std::invalid_argument);

  // A saved training state has the wider critic: an agent without it refuses the file.
  const auto file = std::filesystem::temp_directory_path() / "rlpos-ppo-team-state";
  PpoAgent fresh(spec, 1, 2);
  fresh.SaveTrainingState(file.string());
  PpoAgent again(spec, 1, 2);
  EXPECT_NO_THROW(again.LoadTrainingState(file.string()));
  try {
    PpoAgent(own, 1, 2).LoadTrainingState(file.string());
    ADD_FAILURE() << "a critic without the team state loaded one with it";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": critic"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace rlpos
