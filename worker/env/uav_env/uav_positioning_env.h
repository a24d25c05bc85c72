#pragma once
// The UAV positioning environment, in-process with ns-3 (no sockets, no second process).
// packet fidelity: the full ns-3 simulation advances one decision interval per step
// (Simulator::Stop + Run); each episode rebuilds the network with RngRun = the reset seed.
// analytic fidelity: no packets (AnalyticEvaluator). Episode length and interval from env.
// Several UAVs take turns in Step: each step moves the UAV whose turn it is
// (StepInfo::active_uav, also in the observation), env.turn_steps steps in a row, so one shared
// policy flies them all. Or they move at once as agents in JointStep
// (worker/env/gym/multi_agent.h): one action per UAV, one decision interval, an observation per UAV
// and one team reward.
#include <memory>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/multi_agent.h"
#include "worker/env/gym/reward.h"

namespace rlpos {

class UavNetwork;
class AnalyticEvaluator;
class ModelObservations;
class SharedPlacementMemo;

class UavPositioningEnv : public Env {
 public:
  // Analytic fidelity: with `shared_memo` (one per scenario, shared by the envs of a batch) the
  // states of placements evaluated go there, else into the env's own memo. Packet fidelity
  // ignores it.
  explicit UavPositioningEnv(Scenario scenario,
                             std::shared_ptr<SharedPlacementMemo> shared_memo = nullptr);
  ~UavPositioningEnv() override;

  DiscreteSpace ActionSpace() const override;
  BoxSpace ContinuousActionSpace() const override;
  BoxSpace ObservationSpace() const override;
  std::optional<SlotBlock> UeSlots() const override;
  // At analytic fidelity with the UEs standing still: the UAVs' positions and where the turns
  // stand. At packet level none (the network's queues and clocks carry over).
  std::optional<DeterminingState> Determining() const override;
  std::vector<double> Reset(std::uint64_t seed) override;
  // options.random_start: every UAV starts at RandomStart (moves.h) drawn from `seed`
  // (exploring starts).
  std::vector<double> Reset(std::uint64_t seed, const ResetOptions& options) override;
  // Both throw std::out_of_range for an action outside the env's action space.
  StepResult Step(int action) override;
  StepResult StepContinuous(const std::vector<double>& displacement) override;
  const StepInfo& LastInfo() const override { return info_; }
  // With env.action_mask: "stay" and every move that changes the active UAV's position (not into
  // a wall of its zone, a building or another UAV). Without it, or if nothing moves, every
  // action.
  ActionMask ValidActions() const override { return ValidActionsOf(active_); }
  // The same for UAV `uav`, the others where they are now (in JointStep another UAV's move can
  // still refuse an allowed move: ApplyJointDisplacement).
  ActionMask ValidActionsOf(std::size_t uav) const override;
  std::size_t AgentCount() const override { return scenario_.uavs.size(); }

  // Every UAV at once, actions[u] for UAV u (scenario order): ApplyJointDisplacement's rule,
  // then one decision interval, as Step. The reward, truncation and LastInfo are Step's
  // (LastInfo().active_uav keeps counting Step's turns; JointStep ignores it). Works at both
  // fidelities. Throws std::invalid_argument for a count other than one action per UAV,
  // std::out_of_range for an action outside the action space (naming the UAV), and
  // std::logic_error before the first Reset; a refused call moves nothing.
  JointStepResult JointStep(const std::vector<int>& actions) override;
  // The same with one displacement per UAV (env.action_space "continuous").
  JointStepResult JointStepContinuous(
      const std::vector<std::vector<double>>& displacements) override;
  // Each UAV's observation (AgentObservation) and the global state (MakeState) after the last
  // Reset, Step or JointStep.
  std::vector<std::vector<double>> AgentObservations() const override;
  std::vector<double> TeamStateOf(std::size_t uav) const override;
  std::vector<double> State() const { return MakeState(scenario_, info_); }
  BoxSpace StateSpace() const { return StateBounds(scenario_); }

  const Scenario& scenario() const { return scenario_; }
  int StepsPerEpisode() const { return steps_per_episode_; }
  double RewardOf(const StepInfo& info) const;
  // Wall time spent inside ns-3's Simulator::Run so far (packet fidelity), for benchmarks.
  double WallSecondsInNs3() const { return wall_in_ns3_; }

 private:
  void Observe();  // info_ = the state at the current position (after the last interval)
  // best_reward_ and info_.below_best after Observe; `first`: the episode's first state.
  // Returns the reward here.
  double KeepBest(bool first);
  StepResult MoveTo(const Placement& placement);          // one decision interval at `placement`
  JointStepResult MoveAllTo(const Placement& placement);  // the same, seen by every UAV
  void CheckJointStep(std::size_t actions) const;         // one action per UAV, after a Reset
  bool Continuous() const { return scenario_.env.action_space == "continuous"; }
  // Packet level with several UAVs: a radio per UAV on each UE, re-associated every step.
  bool HandsOver() const { return scenario_.uavs.size() > 1; }
  Scenario scenario_;
  // The buildings indexed for the moves and the model observations (moves.h), built once.
  Obstacles buildings_;
  std::unique_ptr<Reward> reward_;
  std::unique_ptr<UavNetwork> network_;          // packet fidelity
  std::unique_ptr<AnalyticEvaluator> analytic_;  // analytic fidelity
  // The "coverage" and "lookahead" observations (null when not observed), on the analytic
  // model: analytic_, or at packet level a model of their own.
  std::unique_ptr<ModelObservations> model_observations_;
  std::unique_ptr<AnalyticEvaluator> look_model_;
  void FillModelObservations(std::size_t uav, StepInfo& info) const;
  // Each discrete action's displacement (MoveDisplacement), worked out once: the action mask asks
  // for every action at every step.
  std::vector<Vec3> move_displacements_;
  int to_best_ = -1;  // the index of "to_best" in env.actions, or -1
  // Action `action`'s displacement of UAV `uav` now: move_displacements_'s, or for "to_best" a
  // step towards that UAV's coverage pointer (worked out if its map is not current).
  Vec3 DisplacementOf(std::size_t uav, int action) const;
  Placement placement_;
  std::size_t active_ = 0;  // the UAV the next action moves
  StepInfo info_;
  double best_reward_ = 0.0;    // the episode's best reward so far
  bool observes_best_ = false;  // env.observations has "best": it determines what follows too
  int steps_ = 0;
  int steps_per_episode_ = 0;
  double wall_in_ns3_ = 0.0;
};

}  // namespace rlpos
