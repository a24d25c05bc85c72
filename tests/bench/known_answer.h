#pragma once
// Known answers for the agents: DQN and PPO on CartPole-v1, SAC on Pendulum-v1 (Gymnasium's
// dynamics, worker/learning/classic_envs), trained through the trainer's own episodes (RunEpisode)
// and scored greedily at intervals until the usual solved level is first reached. A failure here is
// an implementation bug that tuning on the UAV env could hide.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"

namespace rlpos {

struct KnownAnswerProblem {
  std::string env_name;  // "CartPole-v1" | "Pendulum-v1"
  std::function<std::unique_ptr<Env>()> make_env;
  AgentSpec spec;                    // the hyperparameters (spec.seed is the run's)
  std::int64_t budget_steps = 0;     // training env steps allowed
  std::int64_t eval_every = 0;       // training env steps between greedy evaluations
  int eval_episodes = 0;             // greedy episodes per evaluation
  double solved_return = 0.0;        // the mean greedy return that counts as solved
  double best_episode_return = 0.0;  // no episode returns more (stops a hopeless evaluation)
};

// The problem and CleanRL-like hyperparameters of "dqn", "ppo" or "sac"; throws
// std::invalid_argument for another name.
KnownAnswerProblem KnownAnswerProblemFor(const std::string& algorithm);

struct GreedyEvaluation {
  std::int64_t steps = 0;    // training env steps before it
  int episodes = 0;          // greedy episodes run
  double mean_return = 0.0;  // over them
  bool complete = false;     // all eval_episodes ran (else solving had become impossible)
  bool solved = false;
  double wall_seconds = 0.0;  // since the training started
};

struct KnownAnswerResult {
  std::vector<GreedyEvaluation> evaluations;
  std::optional<std::int64_t> solved_at;  // training steps at the first solved evaluation
  std::int64_t steps = 0;                 // training steps taken
  double wall_seconds = 0.0;
};

// Trains until solved or out of budget. Training episode e runs from seed * 1e6 + e, the
// evaluations from the fixed seeds 1e12 + i (never a training episode's).
KnownAnswerResult RunKnownAnswer(const KnownAnswerProblem& problem, std::uint64_t seed,
                                 const std::function<void(const GreedyEvaluation&)>& on_eval);

}  // namespace rlpos
