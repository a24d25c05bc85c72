#pragma once
// PPO for any scenario: every training episode flies in a scenario of its own, drawn by a
// ScenarioDraw (a fresh generated one, or one of a user's set), agent.ppo.num_envs of them at
// once in lockstep rounds, with one forward pass of the policy for all. The policy is scored
// from time to time on validation scenarios (greedy, from the baseline, over the env's whole
// episode: how it will be used) and the best-scoring one is kept. Seeded: the same draw, seed
// and budget give the same policy, whatever the thread count.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/training/scenario_draw.h"

namespace rlpos {

struct GeneralistOptions {
  std::int64_t steps = 0;             // env steps to learn from (the last round completes)
  int validation_scenarios = 24;      // scored after every validation_every steps and at the end
  std::int64_t validation_every = 0;  // 0: steps / 10
  std::size_t threads = 0;            // 0: min(cores, num_envs)
};

struct GeneralistProgress {
  std::int64_t steps = 0;
  std::int64_t episodes = 0;
  double train_final_reward = 0.0;  // mean final reward of the last round's episodes
  // Set when this progress follows a validation: the policy's mean reward over the oracle's on
  // the validation scenarios, and its worst.
  std::optional<double> validation;
  std::optional<double> validation_worst;
  std::optional<double> best_validation;  // the kept policy's mean
};

// A validation scenario and the analytic oracle's best reward there (the grid search, no
// packet-level re-score): what the policy's flight is measured against.
struct ValidationScenario {
  DrawnScenario drawn;
  double oracle_reward = 0.0;
};

struct ValidationScore {
  std::string origin;  // what ScenarioDraw::Validation said of the scenario
  double final_reward = 0.0;
  double oracle_reward = 0.0;
  double ratio = 0.0;  // final_reward / oracle_reward (1 where the oracle's is 0)
  int n_los = 0;
  std::size_t n_ues = 0;
};

struct GeneralistResult {
  std::int64_t steps = 0;
  std::int64_t episodes = 0;
  std::int64_t kept_at_steps = 0;  // when the kept policy was scored
  double best_validation = 0.0;    // its mean reward over the oracle's on the validation set
  std::vector<ValidationScore> validation;  // its score on each
  std::uint64_t first_draw = 0;             // the training draws, first and last (inclusive)
  std::uint64_t last_draw = 0;
};

using GeneralistProgressCallback = std::function<void(const GeneralistProgress&)>;

// Where a training stands between two rounds: with the agent's training state
// (PpoAgent::SaveTrainingState), all a resumed training needs to go on exactly as the
// uninterrupted one.
struct GeneralistState {
  GeneralistResult result;  // so far
  std::optional<double> best;
  std::int64_t next_validation = 0;
};

// Checkpoints: after a round that leaves the agent between rollouts, when due() says so, save()
// is given the state. `resume`: the state to go on from (the agent's own already loaded).
struct GeneralistCheckpoints {
  std::function<bool()> due;
  std::function<void(const GeneralistState&)> save;
  const GeneralistState* resume = nullptr;
};

// Trains `agent` (built for the draw's spaces and spec) on training draws 0, 1, ... until
// options.steps transitions; leaves the kept policy in the agent. `episode_run`: the RngRun of
// training episode e is episode_run + e (its exploring start).
GeneralistResult TrainGeneralist(const ScenarioDraw& draw, PpoAgent& agent, const AgentSpec& spec,
                                 const GeneralistOptions& options, std::uint64_t episode_run,
                                 const GeneralistProgressCallback& on_progress = nullptr,
                                 const GeneralistCheckpoints& checkpoints = {});

// The draw's first `count` validation scenarios with their oracle rewards, searched over
// `threads` threads (0: the cores).
std::vector<ValidationScenario> ValidationSet(const ScenarioDraw& draw, int count,
                                              std::size_t threads = 0);
// The agent's greedy flight in each, from the baseline, as a policy for any scenario places its
// UAVs: its best step (FlyGreedyToBest with kGeneralPatienceSteps).
std::vector<ValidationScore> ScoreGreedy(const std::vector<ValidationScenario>& scenarios,
                                         Agent& agent, const AgentSpec& spec);

}  // namespace rlpos
