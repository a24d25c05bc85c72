#pragma once
// A PPO policy folder's actor, flown greedy without libtorch: its network read from policy.pt
// (saved_network.h) into the plain-float network PPO computes with (dense_network.h,
// ue_set_network.h), and the actor head PpoAgent acts with (ppo_actor_head.h). So it picks what
// PpoAgent::Act(observation, mask, false) picks, bit for bit, and a process that only places
// UAVs with a policy need not load libtorch (about half a second).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/spaces.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

class DenseNetwork;
class UeSetNetwork;

class PpoGreedyPolicy : public Agent {
 public:
  // The network spec.hidden (and spec.ue_encoder over ue_slots) describe, as PpoAgent builds it.
  // std::invalid_argument for an empty space, or agent.ue_encoder without UE slots.
  PpoGreedyPolicy(const AgentSpec& spec, int observation_dim, int action_count,
                  const std::optional<SlotBlock>& ue_slots);
  ~PpoGreedyPolicy() override;
  std::string Algorithm() const override { return "ppo"; }
  // The most probable allowed action; std::logic_error with explore (it has no sampler).
  int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) override;
  // Reads DIRECTORY/policy.pt (PpoNetwork::Load's errors, as std::runtime_error).
  void Load(const std::string& directory) override;
  // It flies; it does not learn: each of these throws std::logic_error.
  std::optional<double> Observe(Transition transition) override;
  void KeepPolicy() override;
  void RestoreKeptPolicy() override;
  void Save(const std::string& directory) const override;

 private:
  int observation_dim_;
  int action_count_;
  std::unique_ptr<DenseNetwork> mlp_;  // one of the two
  std::unique_ptr<UeSetNetwork> set_;
  std::vector<float> logits_;
  std::vector<float> probabilities_;
};

}  // namespace rlpos
