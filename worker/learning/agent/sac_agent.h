#pragma once
// Soft Actor-Critic (libtorch) on a continuous action space: a tanh-squashed Gaussian policy,
// twin Q-networks with Polyak-averaged targets, experience replay and the entropy temperature
// tuned towards -|A| (or fixed by agent.sac.alpha). Seeded: the same seed, spaces and
// transitions give the same networks.
#include <memory>

#include "common/scenario/scenario.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

class SacAgent : public Agent {
 public:
  SacAgent(const AgentSpec& spec, int observation_dim, int action_dim);
  ~SacAgent() override;
  std::string Algorithm() const override;
  bool Continuous() const override { return true; }
  int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) override;
  // explore: uniform during agent.sac.warmup_steps, then a sample of the policy; otherwise
  // tanh of the policy's mean.
  std::vector<float> ActContinuous(const std::vector<float>& observation, bool explore) override;
  std::optional<double> Observe(Transition transition) override;
  std::string ProgressText() const override;  // "alpha a", the entropy temperature
  void KeepPolicy() override;
  void RestoreKeptPolicy() override;
  void Save(const std::string& directory) const override;
  void Load(const std::string& directory) override;
  double Alpha() const;  // the entropy temperature now

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rlpos
