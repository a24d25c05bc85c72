#include "tests/bench/known_answer.h"

#include <chrono>
#include <stdexcept>

#include "worker/learning/agent/make_agent.h"
#include "worker/learning/agent_base/trainer.h"
#include "worker/learning/classic_envs/cartpole_env.h"
#include "worker/learning/classic_envs/pendulum_env.h"

namespace rlpos {
namespace {

constexpr std::uint64_t kEvalSeeds = 1000000000000ULL;
constexpr std::uint64_t kTrainSeedStride = 1000000ULL;

// The settings every run shares: the problems' rewards are the objective itself (CartPole's is
// a constant 1: standardised, it would be 0 and teach nothing).
AgentSpec CommonSpec(const std::string& algorithm) {
  AgentSpec spec;
  spec.algorithm = algorithm;
  spec.normalise_rewards = false;
  return spec;
}

// CleanRL's dqn.py for CartPole-v1 (120-84 network, lr 2.5e-4, replay 10,000, batch 128,
// gamma 0.99, target refresh every 500 steps, epsilon to 0.05) except the schedule: our DQN
// learns at every step, not every 10th, so it explores for 10,000 steps, not 250,000.
KnownAnswerProblem DqnCartPole() {
  KnownAnswerProblem p;
  p.env_name = "CartPole-v1";
  p.make_env = [] { return std::make_unique<CartPoleEnv>(); };
  p.spec = CommonSpec("dqn");
  p.spec.hidden = {120, 84};
  DqnSpec& dqn = p.spec.dqn;
  dqn.learning_rate = 2.5e-4;
  dqn.replay_capacity = 10000;
  dqn.batch_size = 128;
  dqn.gamma = 0.99;
  dqn.epsilon_start = 1.0;
  dqn.epsilon_end = 0.05;
  dqn.epsilon_decay_steps = 10000;
  dqn.target_update_interval = 500;
  dqn.warmup_steps = 1000;
  dqn.double_dqn = false;
  p.budget_steps = 200000;
  p.eval_every = 5000;
  p.eval_episodes = 100;
  p.solved_return = 475.0;
  p.best_episode_return = 500.0;
  return p;
}

// CleanRL's ppo.py for CartPole-v1: 64-64 networks, lr 2.5e-4 annealed to 0 over the budget,
// 512 transitions per update (their 4 envs x 128 steps), 4 epochs of 4 minibatches, gamma 0.99,
// GAE lambda 0.95, clip 0.2, entropy 0.01, value 0.5, gradient norm 0.5.
KnownAnswerProblem PpoCartPole() {
  KnownAnswerProblem p = DqnCartPole();
  p.spec = CommonSpec("ppo");
  p.spec.hidden = {64, 64};
  PpoSpec& ppo = p.spec.ppo;
  ppo.learning_rate = 2.5e-4;
  ppo.anneal_learning_rate = true;
  ppo.gamma = 0.99;
  ppo.gae_lambda = 0.95;
  ppo.clip = 0.2;
  ppo.entropy_coefficient = 0.01;
  ppo.value_coefficient = 0.5;
  ppo.max_grad_norm = 0.5;
  ppo.rollout_steps = 512;
  ppo.epochs = 4;
  ppo.minibatches = 4;
  return p;
}

// CleanRL's sac_continuous_action.py (policy lr 3e-4, Q lr 1e-3, the temperature's too, batch
// 256, gamma 0.99, tau 0.005, automatic temperature) with 64-64 networks, not 256-256 (a
// sixteenth of the arithmetic: a CI run in minutes, not a quarter of an hour), and 1,000 random
// steps (CleanRL: 5,000, a sixth of this budget).
KnownAnswerProblem SacPendulum() {
  KnownAnswerProblem p;
  p.env_name = "Pendulum-v1";
  p.make_env = [] { return std::make_unique<PendulumEnv>(); };
  p.spec = CommonSpec("sac");
  p.spec.hidden = {64, 64};
  SacSpec& sac = p.spec.sac;
  sac.policy_learning_rate = 3e-4;
  sac.q_learning_rate = 1e-3;
  sac.batch_size = 256;
  sac.gamma = 0.99;
  sac.tau = 0.005;
  sac.warmup_steps = 1000;
  sac.update_interval = 1;
  sac.alpha.reset();
  p.budget_steps = 30000;
  p.eval_every = 1000;
  p.eval_episodes = 20;
  p.solved_return = -200.0;
  p.best_episode_return = 0.0;
  return p;
}

// Greedy episodes from the evaluation seeds; stops once even perfect episodes could no longer
// lift the mean to the solved level.
GreedyEvaluation EvaluateGreedily(const KnownAnswerProblem& problem, Env& env, Agent& agent) {
  GreedyEvaluation e;
  double sum = 0.0;
  const double needed = problem.solved_return * problem.eval_episodes;
  for (int i = 0; i < problem.eval_episodes; ++i) {
    sum += RunEpisode(env, agent, kEvalSeeds + static_cast<std::uint64_t>(i), false).total_reward;
    ++e.episodes;
    const int left = problem.eval_episodes - e.episodes;
    if (sum + left * problem.best_episode_return < needed)
      break;
  }
  e.mean_return = sum / e.episodes;
  e.complete = e.episodes == problem.eval_episodes;
  e.solved = e.complete && e.mean_return >= problem.solved_return;
  return e;
}

}  // namespace

KnownAnswerProblem KnownAnswerProblemFor(const std::string& algorithm) {
  if (algorithm == "dqn")
    return DqnCartPole();
  if (algorithm == "ppo")
    return PpoCartPole();
  if (algorithm == "sac")
    return SacPendulum();
  throw std::invalid_argument("unknown algorithm '" + algorithm + "' (dqn, ppo or sac)");
}

KnownAnswerResult RunKnownAnswer(const KnownAnswerProblem& problem, std::uint64_t seed,
                                 const std::function<void(const GreedyEvaluation&)>& on_eval) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  AgentSpec spec = problem.spec;
  spec.seed = seed;
  const std::unique_ptr<Env> env = problem.make_env();
  const std::unique_ptr<Agent> agent = MakeAgent(spec, *env, problem.budget_steps);
  KnownAnswerResult result;
  std::int64_t next_eval = problem.eval_every;
  for (std::uint64_t episode = 0; result.steps < problem.budget_steps; ++episode) {
    result.steps += RunEpisode(*env, *agent, seed * kTrainSeedStride + episode, true).steps;
    if (result.steps < next_eval && result.steps < problem.budget_steps)
      continue;
    next_eval += problem.eval_every;
    GreedyEvaluation e = EvaluateGreedily(problem, *env, *agent);
    e.steps = result.steps;
    e.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.evaluations.push_back(e);
    if (on_eval)
      on_eval(e);
    if (e.solved) {
      result.solved_at = e.steps;
      break;
    }
  }
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace rlpos
