#pragma once
// The environment interface the agents see (Gymnasium semantics): reset(seed) -> observation;
// step(action) -> observation, reward, terminated, truncated, info.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

struct StepInfo {
  Placement positions;       // one per UAV
  std::vector<int> serving;  // per UE: the index of its UAV
  int active_uav = 0;        // the UAV the next action moves (several UAVs take turns)
  int n_los = 0;
  std::vector<std::uint8_t> los;  // per UE: 1 if its line to its serving UAV is clear
  double throughput_mbps = 0.0;
  int demands_met = 0;
  std::vector<double> snr_db;
  // The model's look around, where env.observations asks for it (general_observation.h):
  // "coverage" (2 x env.coverage_map^2 + 3 values) and "lookahead" (one per move).
  std::vector<double> coverage;
  std::vector<double> lookahead;
  // The episode's best reward so far (since its reset, this state included) minus the reward
  // here: 0 at a new best (the "best" observation).
  double below_best = 0.0;
};

struct StepResult {
  std::vector<double> observation;
  double reward = 0.0;
  bool terminated = false;  // a terminal state was reached
  bool truncated = false;   // the episode ran out of time
  StepInfo info;
};

// A joint step: every UAV moved once, at once. One observation per UAV (its own view), one team
// reward.
struct JointStepResult {
  std::vector<std::vector<double>> observations;  // [agent]: its own view
  std::vector<double> state;                      // the global state, if the env has one
  double reward = 0.0;                            // the env's reward, shared by the team
  bool terminated = false;
  bool truncated = false;
  StepInfo info;
};

// Where an episode stands, when everything still to come follows from it: `key` holds it as bits
// (two moments of equal keys give the same observations, masks, rewards and infos under the
// same actions), and the episode ends by its time limit only, after `steps_left` more steps.
struct DeterminingState {
  std::vector<std::uint64_t> key;
  int steps_left = 0;
};

// Gymnasium's reset(options=...): what an env may do differently in one episode.
struct ResetOptions {
  // Start from a state drawn from the seed instead of the usual initial state (exploring
  // starts, for training). An env whose initial state is random already ignores it.
  bool random_start = false;
};

class Env {
 public:
  virtual ~Env() = default;
  // The discrete actions; n = 0 for an env with a continuous action space.
  virtual DiscreteSpace ActionSpace() const = 0;
  // The continuous action space; Dim() = 0 for an env with discrete actions.
  virtual BoxSpace ContinuousActionSpace() const { return {}; }
  virtual BoxSpace ObservationSpace() const = 0;
  virtual std::vector<double> Reset(std::uint64_t seed) = 0;
  // Reset with options; an env that has none to offer resets as Reset(seed).
  virtual std::vector<double> Reset(std::uint64_t seed, const ResetOptions& /*options*/) {
    return Reset(seed);
  }
  virtual StepResult Step(int action) = 0;
  // A step with an action of ContinuousActionSpace().
  virtual StepResult StepContinuous(const std::vector<double>& /*action*/) {
    throw std::out_of_range("this env takes discrete actions");
  }
  // The info of the state after the last Reset/Step.
  virtual const StepInfo& LastInfo() const = 0;
  // The actions allowed in the current state; empty (the default) allows all.
  virtual ActionMask ValidActions() const { return {}; }
  // Where the observation holds one slot per UE (a set a network may take as one), if it does.
  virtual std::optional<SlotBlock> UeSlots() const { return std::nullopt; }
  // The state the rest of the episode follows from, if the env can tell (empty, the default,
  // when what is to come also depends on what it cannot expose, such as a simulator's queues).
  // An env that tells it after a Reset tells it after every step of that episode.
  virtual std::optional<DeterminingState> Determining() const { return std::nullopt; }

  // UAV (agent) `agent`'s team state (team_state.h) after the last Reset or step: what a
  // centralised critic sees beside its observation. std::logic_error for an env without one.
  virtual std::vector<double> TeamStateOf(std::size_t /*agent*/) const {
    throw std::logic_error("this env has no team state for a centralised critic");
  }

  // Several agents that act at once (several UAVs: every UAV moves in each step, as in
  // PettingZoo's ParallelEnv). An env of one agent has none of these.
  virtual std::size_t AgentCount() const { return 1; }
  // Each agent's observation after the last Reset or step.
  virtual std::vector<std::vector<double>> AgentObservations() const {
    throw std::logic_error("this env has one agent");
  }
  // The actions agent `agent` may take now (empty: all).
  virtual ActionMask ValidActionsOf(std::size_t /*agent*/) const { return ValidActions(); }
  virtual JointStepResult JointStep(const std::vector<int>& /*actions*/) {
    throw std::logic_error("this env has one agent");
  }
  virtual JointStepResult JointStepContinuous(const std::vector<std::vector<double>>& /*actions*/) {
    throw std::logic_error("this env has one agent");
  }
};

}  // namespace rlpos
