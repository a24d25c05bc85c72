#include "worker/learning/agent_base/ppo_greedy_policy.h"

#include <algorithm>
#include <stdexcept>

#include "worker/learning/agent_base/dense_network.h"
#include "worker/learning/agent_base/ppo_actor_head.h"
#include "worker/learning/agent_base/ppo_objective.h"
#include "worker/learning/agent_base/saved_network.h"
#include "worker/learning/agent_base/ue_set_network.h"

namespace rlpos {

PpoGreedyPolicy::PpoGreedyPolicy(const AgentSpec& spec, int observation_dim, int action_count,
                                 const std::optional<SlotBlock>& ue_slots)
    : observation_dim_(observation_dim),
      action_count_(action_count),
      logits_(static_cast<std::size_t>(std::max(action_count, 0))),
      probabilities_(logits_.size()) {
  if (observation_dim <= 0 || action_count <= 0)
    throw std::invalid_argument("PPO needs a non-empty observation and action space");
  if (spec.ue_encoder.empty()) {
    std::vector<int> widths{observation_dim};
    widths.insert(widths.end(), spec.hidden.begin(), spec.hidden.end());
    widths.push_back(action_count);
    mlp_ = std::make_unique<DenseNetwork>(widths);
    return;
  }
  if (!ue_slots)
    throw std::invalid_argument("agent.ue_encoder needs \"ues\" in env.observations");
  set_ = std::make_unique<UeSetNetwork>(observation_dim, *ue_slots, spec.ue_encoder, spec.hidden,
                                        action_count);
}

PpoGreedyPolicy::~PpoGreedyPolicy() = default;

int PpoGreedyPolicy::Act(const std::vector<float>& observation, const ActionMask& mask,
                         bool explore) {
  if (explore)
    throw std::logic_error("a greedy policy does not explore");
  if (static_cast<int>(observation.size()) < observation_dim_)
    throw std::invalid_argument("PpoGreedyPolicy: an observation shorter than the network's input");
  if (set_)
    set_->Forward(observation.data(), 1, logits_.data());
  else
    mlp_->Forward(observation.data(), 1, logits_.data());
  MaskLogits(mask, action_count_, logits_.data());
  Softmax(logits_.data(), action_count_, probabilities_.data());
  return MostProbableAllowed(probabilities_.data(), mask, action_count_);
}

void PpoGreedyPolicy::Load(const std::string& directory) {
  if (set_)
    LoadSavedNetwork(directory + "/policy.pt", *set_);
  else
    LoadSavedNetwork(directory + "/policy.pt", *mlp_);
}

std::optional<double> PpoGreedyPolicy::Observe(Transition /*transition*/) {
  throw std::logic_error("a greedy policy does not learn");
}

void PpoGreedyPolicy::KeepPolicy() {
  throw std::logic_error("a greedy policy does not learn");
}

void PpoGreedyPolicy::RestoreKeptPolicy() {
  throw std::logic_error("a greedy policy does not learn");
}

void PpoGreedyPolicy::Save(const std::string& /*directory*/) const {
  throw std::logic_error("a greedy policy is read, not written");
}

}  // namespace rlpos
