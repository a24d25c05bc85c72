#pragma once
// What an RL algorithm offers the trainer; it sees only the env's spaces and transitions, so a
// second algorithm drops in beside DQN.
#include <string>
#include <vector>

#include "agent/replay_buffer.h"

namespace rlpos {

class Agent {
 public:
  virtual ~Agent() = default;
  // An action for `observation` (already normalised) among those `mask` allows; `explore`
  // enables the behaviour policy.
  virtual int Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) = 0;
  // Learns from one transition (stores it, maybe trains). Returns the loss, or < 0 if no update.
  virtual double Observe(Transition transition) = 0;
  virtual double Epsilon() const = 0;
  virtual void Save(const std::string& directory) const = 0;
  virtual void Load(const std::string& directory) = 0;
};

}  // namespace rlpos
