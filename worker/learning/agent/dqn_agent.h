#pragma once
// Deep Q-Network (libtorch): an MLP Q-function, experience replay, a target network, epsilon-
// greedy behaviour; Double DQN as an option. It reads only its own settings (AgentSpec::dqn,
// common/scenario/dqn_hyperparameters.h, which says which are the paper's Table II) and the
// shared ones. Seeded: the same seed, spaces and transitions give the same network.
#include <memory>

#include "common/scenario/scenario.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

class DqnAgent : public Agent {
 public:
  DqnAgent(const AgentSpec& spec, int observation_dim, int action_count);
  ~DqnAgent() override;
  int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) override;
  std::optional<double> Observe(Transition transition) override;
  double Epsilon() const override;
  std::string ProgressText() const override;  // "epsilon e"
  std::string Algorithm() const override;
  void KeepPolicy() override;
  void RestoreKeptPolicy() override;
  void Save(const std::string& directory) const override;
  void Load(const std::string& directory) override;
  // Q-values of an observation (for tests and inspection).
  std::vector<float> QValues(const std::vector<float>& observation) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rlpos
