#pragma once
// What an RL algorithm offers the trainer; it sees only the env's spaces and transitions, so the
// algorithms (DQN, PPO, SAC) are interchangeable behind it.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "worker/learning/agent_base/replay_buffer.h"

namespace rlpos {

class Agent {
 public:
  virtual ~Agent() = default;
  virtual std::string Algorithm() const = 0;  // "dqn" | "ppo" | "sac"
  // True for an agent of a continuous action space (ActContinuous, not Act).
  virtual bool Continuous() const { return false; }
  // An action for `observation` (already normalised) among those `mask` allows; `explore`
  // enables the behaviour policy.
  virtual int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) = 0;
  // A continuous action, each component in [-1, 1] (the trainer maps it onto the env's Box).
  virtual std::vector<float> ActContinuous(const std::vector<float>& /*observation*/,
                                           bool /*explore*/) {
    throw std::logic_error(Algorithm() + " acts on discrete actions");
  }
  // Learns from one transition (stores it, maybe trains): the loss of the update it made, if
  // any. The transition is of the last Act/ActContinuous with explore.
  virtual std::optional<double> Observe(Transition transition) = 0;
  // Several agents that act at once with this one policy (parameter sharing): an action for
  // each observation (masks[i] for observations[i]), then ObserveEach with their transitions in
  // the same order. By default Act and Observe for each in turn; an agent whose Observe depends
  // on the Act before it (PPO's log-probabilities) overrides both.
  virtual std::vector<int> ActEach(const std::vector<std::vector<float>>& observations,
                                   const std::vector<ActionMask>& masks, bool explore) {
    std::vector<int> actions;
    for (std::size_t i = 0; i < observations.size(); ++i)
      actions.push_back(Act(observations[i], masks.at(i), explore));
    return actions;
  }
  // The loss of the last update the transitions led to, if any.
  virtual std::optional<double> ObserveEach(std::vector<Transition> transitions) {
    std::optional<double> loss;
    for (Transition& t : transitions) {
      if (const std::optional<double> l = Observe(std::move(t)))
        loss = l;
    }
    return loss;
  }
  // Whether each transition must carry the acting agent's team state (Env::TeamStateOf), for a
  // centralised critic (agent.ppo.centralised_critic).
  virtual bool NeedsTeamState() const { return false; }
  // DQN's exploration rate; 0 for the algorithms that explore by a stochastic policy.
  virtual double Epsilon() const { return 0.0; }
  // What a training's progress line shows of the agent's own learning, named: DQN's exploration
  // rate ("epsilon 0.42"), PPO's policy entropy and learning rate, SAC's entropy temperature;
  // "" when there is nothing to show yet.
  virtual std::string ProgressText() const { return ""; }
  // Remembers the networks the policy acts with (those Save writes), in memory, replacing what
  // it remembered before; RestoreKeptPolicy acts and saves with them again. For a trainer that
  // keeps the best policy it has scored; learning on after a restore is not what they are for.
  virtual void KeepPolicy() = 0;
  // Throws std::logic_error if no policy was kept.
  virtual void RestoreKeptPolicy() = 0;
  virtual void Save(const std::string& directory) const = 0;
  virtual void Load(const std::string& directory) = 0;
};

}  // namespace rlpos
