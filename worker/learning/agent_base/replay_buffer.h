#pragma once
// Uniform experience replay: a ring buffer of transitions with seeded sampling.
#include <cstdint>
#include <random>
#include <vector>

#include "worker/env/gym/spaces.h"

namespace rlpos {

struct Transition {
  std::vector<float> observation;
  int action = 0;
  float reward = 0.0f;
  std::vector<float> next_observation;
  bool terminal = false;  // no bootstrap from next_observation (truncation is not terminal)
  ActionMask next_mask;   // actions allowed after the step (the bootstrap maximises over them)
  std::vector<float> continuous_action;  // continuous agents: the action, in [-1, 1]
  bool episode_end = false;              // terminal or truncated: returns are not carried across it
  // With a centralised critic (agent.ppo.centralised_critic): the acting agent's team state
  // (team_state.h) before and after the step. Empty otherwise.
  std::vector<float> team_state = {};  // initialised: brace-initialised transitions omit both
  std::vector<float> next_team_state = {};
};

class ReplayBuffer {
 public:
  explicit ReplayBuffer(std::size_t capacity);
  void Add(Transition t);
  std::size_t Size() const { return items_.size(); }
  std::size_t Capacity() const { return capacity_; }
  // `batch` indices drawn uniformly with replacement.
  std::vector<std::size_t> SampleIndices(std::size_t batch, std::mt19937_64& rng) const;
  const Transition& At(std::size_t i) const { return items_[i]; }

 private:
  std::size_t capacity_;
  std::size_t next_ = 0;  // slot to overwrite once full
  std::vector<Transition> items_;
};

// Linear epsilon from `start` to `end` over `decay_steps` (constant `start` if 0 steps... and
// `end` afterwards). The paper trains with epsilon = 1 throughout.
struct EpsilonSchedule {
  double start = 1.0;
  double end = 1.0;
  int decay_steps = 0;
  double At(std::int64_t step) const {
    if (decay_steps <= 0 || step >= decay_steps)
      return decay_steps <= 0 ? start : end;
    return start + (end - start) * static_cast<double>(step) / decay_steps;
  }
};

}  // namespace rlpos
