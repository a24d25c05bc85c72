#pragma once
// Proximal Policy Optimization on the discrete moves: separate actor and critic MLPs (initialised,
// saved and loaded by libtorch, computed in plain float: dense_network.h says why),
// the clipped surrogate objective, generalised advantage estimation, an entropy bonus and
// gradient-norm clipping, updated every agent.ppo.rollout_steps x num_envs transitions (rollouts
// of rollout_steps from each of num_envs envs, as CleanRL's). Seeded: the same
// seed, spaces and transitions give the same network. The rollout may come from one env (Act,
// Observe) or from several at once (ActBatch, ObserveBatch: one forward pass for them all).
#include <cstdint>
#include <memory>
#include <optional>

#include "common/scenario/scenario.h"
#include "worker/env/gym/spaces.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

class PpoAgent : public Agent {
 public:
  // training_steps: the transitions it will learn from, over which agent.ppo.anneal_learning_rate
  // lowers the rate to 0 (0: unknown, the rate stays). ue_slots: where the observation's UE
  // slots lie (Env::UeSlots), which spec.ue_encoder needs (std::invalid_argument without).
  PpoAgent(const AgentSpec& spec, int observation_dim, int action_count,
           std::int64_t training_steps = 0,
           const std::optional<SlotBlock>& ue_slots = std::nullopt);
  ~PpoAgent() override;
  std::string Algorithm() const override;
  // explore: a sample of the policy; otherwise its most probable allowed action.
  int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) override;
  std::optional<double> Observe(Transition transition) override;
  // Exploring actions for several envs' observations (normalised), one forward pass for all:
  // row r is sampled among what masks[r] allows, rows in order, from the agent's generator (one
  // row gives what Act gives). masks: one per row, or empty for no masks.
  std::vector<int> ActBatch(const std::vector<std::vector<float>>& observations,
                            const std::vector<ActionMask>& masks);
  // The transitions of the rows of the last ActBatch, in its order; envs[r] names row r's env
  // (its stream: GAE carries no advantage from one env's transitions to another's). Learns once
  // the rollout holds rollout_steps x num_envs transitions: the mean loss of that update.
  std::optional<double> ObserveBatch(std::vector<Transition> transitions,
                                     const std::vector<int>& envs);
  // Each observation's transitions form a stream of their own (ActBatch, ObserveBatch).
  std::vector<int> ActEach(const std::vector<std::vector<float>>& observations,
                           const std::vector<ActionMask>& masks, bool explore) override;
  std::optional<double> ObserveEach(std::vector<Transition> transitions) override;
  bool NeedsTeamState() const override;
  // "entropy H, learning rate r": the policy's mean entropy over the last update's minibatches
  // (as each was before its step), and the rate now; the rate alone before the first update.
  std::string ProgressText() const override;
  void KeepPolicy() override;
  void RestoreKeptPolicy() override;
  void Save(const std::string& directory) const override;
  void Load(const std::string& directory) override;
  // The policy's action probabilities (for tests and inspection).
  std::vector<float> Probabilities(const std::vector<float>& observation,
                                   const ActionMask& mask) const;
  // The learning rate of the last update (agent.ppo.learning_rate before the first).
  double LearningRate() const;
  // Whether the rollout is empty (just after an update, or before the first step): the moment
  // a checkpoint can hold the whole training state.
  bool AtRolloutStart() const;
  // The exact training state (networks, Adam, the generator, reward statistics, the kept policy,
  // the updates done) into / from FILE, so that a resumed training computes what the
  // uninterrupted one would have. Save: std::logic_error unless AtRolloutStart(). Load: a
  // std::runtime_error naming the file for a file of another agent's shape, or damaged.
  void SaveTrainingState(const std::string& file) const;
  void LoadTrainingState(const std::string& file);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rlpos
