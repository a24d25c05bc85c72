#pragma once
// Episodes of agent-env interaction: training (behaviour policy, learning) and evaluation
// (greedy). The final greedy position of the evaluation episode is the RL positioner's answer.
// With agent.eval_interval, greedy checkpoint episodes score the policy during training and the
// best one is kept for the evaluation: a policy that peaks and then drifts (PPO's late collapse,
// a greedy policy worse than its stochastic one) still answers with its best.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

struct EpisodeRecord {
  int episode = 0;
  bool evaluation = false;  // greedy (a checkpoint or the final evaluation)
  bool checkpoint = false;  // a greedy episode scoring the policy after training episode `episode`
  int steps = 0;
  double total_reward = 0.0;
  double epsilon = 0.0;
  int updates = 0;         // learning steps the agent took in this episode
  double mean_loss = 0.0;  // their mean loss (0 without updates)
  double final_reward = 0.0;
  StepInfo final_info;
};

struct TrainResult {
  // One record per episode: training (each followed by its checkpoint, if any), then evaluation.
  std::vector<EpisodeRecord> curve;
  int policy_episode = 0;    // the training episode after which the kept policy stood
  int episodes_trained = 0;  // train_episodes, or fewer when early stopping ended training
  StepInfo final_info;       // state at the end of the last evaluation episode
  double final_reward = 0.0;
};

using EpisodeCallback = std::function<void(const EpisodeRecord&)>;
// Called after every step: step number (from 1), the action taken (its index; 0 for a
// continuous one) and what it led to.
using StepCallback = std::function<void(int step, int action, const StepResult&)>;

// A continuous agent's action (each component in [-1, 1]) mapped onto the env's Box.
std::vector<double> ScaleToBox(const std::vector<float>& unit, const BoxSpace& box);

// Agent `agent`'s team state in `env` now (Env::TeamStateOf), as a centralised critic takes it.
std::vector<float> TeamStateFor(const Env& env, std::size_t agent);

// How one episode differs from the env's own: its reset options, a step limit (0: none) after
// which it is truncated, and whether the env's agents act at once (Env::JointStep, each from its
// own observation, agent.joint_steps) rather than in turns.
struct EpisodeOptions {
  ResetOptions reset;
  int max_steps = 0;
  bool joint = false;
};

// The options of a greedy episode (a checkpoint, the evaluation, a replay) under `spec`.
EpisodeOptions GreedyEpisodeOptions(const AgentSpec& spec);

// The options of training episode `episode` (from 0) under `spec` (agent.exploring_starts,
// agent.baseline_start_every, agent.train_episode_steps).
EpisodeOptions TrainingEpisodeOptions(const AgentSpec& spec, int episode);

// Runs one episode from env.Reset(seed, options.reset). With `learn`, the agent explores and
// learns. With options.joint and an env of several agents, every step is one Env::JointStep:
// each agent's transition (its observation, action and mask, the shared reward) is learnt from
// (Agent::ObserveEach); on_step sees the joint step as a StepResult of the first agent's
// observation and action.
EpisodeRecord RunEpisode(Env& env, Agent& agent, std::uint64_t seed, bool learn,
                         const StepCallback& on_step = nullptr, const EpisodeOptions& options = {});

// The seed Train gives evaluation episode k (from 0) of a training from `seed`: the ones after
// the training episodes'. Checkpoints fly k = 0; the last one's end is TrainResult::final_info,
// which a replay of the policy reproduces (a policy folder records it).
std::uint64_t EvaluationSeed(const AgentSpec& spec, std::uint64_t seed, int k);

// The greedy checkpoints of a training (spec.eval_interval) and the best policy they keep: the
// part of Train that does not depend on how the training episodes are collected.
class Checkpoints {
 public:
  // Whether a checkpoint follows the training episodes up to `done` (from 1), `before` of them
  // having been trained at the last call: one per eval_interval crossed, and after the last.
  static bool Due(const AgentSpec& spec, int before, int done);
  // Scores the policy by a greedy episode from the evaluation's first seed after training
  // episode `episode`, keeps it if no earlier one scored more, and records it into `result`.
  EpisodeRecord Score(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                      int episode, TrainResult& result);
  // spec.early_stop_checkpoints in a row did not beat the kept policy.
  bool StopEarly(const AgentSpec& spec) const;
  // Restores the kept policy (if any) and runs the evaluation episodes into `result`.
  void Evaluate(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                TrainResult& result, const EpisodeCallback& on_episode,
                const StepCallback& on_eval_step) const;

 private:
  std::optional<double> kept_;  // the kept policy's checkpoint reward
  int stale_ = 0;               // checkpoints in a row that did not beat it
};

// What a training transition learns from: the env's `reward`, or with agent.improvement_reward
// its rise above `best`, the episode's best reward so far (from its start state on), which this
// updates. Summed over an episode, the rises are its best reward minus its start's.
double LearntReward(const AgentSpec& spec, double reward, double& best);

// Refuses (std::invalid_argument, naming the key) what only training across scenarios learns
// with: agent.improvement_reward, which measures each step against its episode's start state.
void CheckPerScenarioTraining(const AgentSpec& spec);

// spec.train_episodes learning episodes (seeds seed, seed+1, ...), then spec.eval_episodes
// greedy ones. With spec.eval_interval n > 0, a greedy checkpoint episode from the evaluation's
// seed after every n-th training episode and after the last; the policy of the highest final
// reward (the latest of equals) is restored for the evaluation; with spec.early_stop_checkpoints
// m > 0, training ends after m checkpoints in a row that do not beat the kept reward (the
// evaluation keeps its seeds, seed + train_episodes, ...). `on_episode` is called after each
// episode (progress, learning curve), `on_eval_step` after each step of the evaluation episodes
// (the flown trajectory).
TrainResult Train(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                  const EpisodeCallback& on_episode = nullptr,
                  const StepCallback& on_eval_step = nullptr);

}  // namespace rlpos
