#include "worker/env/uav_env/uav_positioning_env.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/scenario/building_obstacles.h"
#include "common/scenario/number_text.h"
#include "worker/env/gym/moves.h"
#include "worker/env/gym/team_state.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/bit_keys.h"
#include "worker/env/uav_env/model_observations.h"

namespace rlpos {

UavPositioningEnv::UavPositioningEnv(Scenario scenario,
                                     std::shared_ptr<SharedPlacementMemo> shared_memo)
    : scenario_(std::move(scenario)),
      buildings_(BuildingObstacles(scenario_.buildings)),
      reward_(MakeReward(scenario_.env.reward)) {
  steps_per_episode_ = static_cast<int>(
      std::llround(scenario_.env.episode_duration / scenario_.env.decision_interval));
  if (!Continuous()) {
    for (std::size_t a = 0; a < scenario_.env.actions.size(); ++a)
      move_displacements_.push_back(MoveDisplacement(scenario_, static_cast<int>(a)));
    to_best_ = ToBestAction(scenario_);
  }
  if (scenario_.env.fidelity == "analytic") {
    analytic_ = std::make_unique<AnalyticEvaluator>(scenario_, std::move(shared_memo));
  }
  const auto& fields = scenario_.env.observations;
  observes_best_ = std::find(fields.begin(), fields.end(), "best") != fields.end();
  model_observations_ = ModelObservations::For(scenario_, buildings_);
  if (model_observations_ && !analytic_)
    look_model_ = std::make_unique<AnalyticEvaluator>(scenario_);
}

void UavPositioningEnv::FillModelObservations(std::size_t uav, StepInfo& info) const {
  AnalyticEvaluator& model = analytic_ ? *analytic_ : *look_model_;
  // The model's reward here, not ns-3's measured one: a lookahead is the model's change.
  const double here = analytic_ ? RewardOf(info) : RewardOf(model.Evaluate(placement_));
  const auto reward_of = [this](const StepInfo& i) { return RewardOf(i); };
  model_observations_->Fill(placement_, uav, here, model, reward_of, info);
}

Vec3 UavPositioningEnv::DisplacementOf(std::size_t uav, int action) const {
  if (action != to_best_)
    return move_displacements_[static_cast<std::size_t>(action)];
  if (!model_observations_->PointerTargetOf(uav, placement_)) {
    // another UAV's map, not worked out since the last move
    StepInfo view = info_;
    FillModelObservations(uav, view);
  }
  return model_observations_->ToBestMove(uav, placement_);
}

UavPositioningEnv::~UavPositioningEnv() = default;

DiscreteSpace UavPositioningEnv::ActionSpace() const {
  return {Continuous() ? 0 : static_cast<int>(scenario_.env.actions.size())};
}

BoxSpace UavPositioningEnv::ContinuousActionSpace() const {
  return Continuous() ? DisplacementBounds(scenario_) : BoxSpace{};
}

BoxSpace UavPositioningEnv::ObservationSpace() const {
  return ObservationBounds(scenario_);
}

std::optional<SlotBlock> UavPositioningEnv::UeSlots() const {
  return UeSlotBlock(scenario_);
}

std::optional<DeterminingState> UavPositioningEnv::Determining() const {
  // At analytic fidelity a step is a pure function of the placement (the UEs stand where the
  // scenario puts them) and the next turn of where the turns stand; nothing terminates early.
  if (!analytic_ || placement_.empty())
    return std::nullopt;
  DeterminingState state;
  state.key.reserve(3 * placement_.size() + 1);
  for (const Vec3& at : placement_)
    state.key.insert(state.key.end(), {DoubleBits(at.x), DoubleBits(at.y), DoubleBits(at.z)});
  const int round = scenario_.env.turn_steps * static_cast<int>(placement_.size());
  state.key.push_back(static_cast<std::uint64_t>(steps_ % round));
  if (observes_best_)  // a placement met again, after a better one, is observed otherwise
    state.key.push_back(DoubleBits(best_reward_));
  state.steps_left = steps_per_episode_ - steps_;
  return state;
}

ActionMask UavPositioningEnv::ValidActionsOf(std::size_t uav) const {
  if (!scenario_.env.action_mask || Continuous())
    return {};
  const auto& actions = scenario_.env.actions;
  ActionMask mask(actions.size(), 0);
  bool moves = false;
  for (std::size_t a = 0; a < actions.size(); ++a) {
    const Vec3& at = placement_.at(uav);
    const Vec3 to = DisplacementTarget(scenario_, buildings_, uav,
                                       DisplacementOf(uav, static_cast<int>(a)), placement_);
    const bool changes = to.x != at.x || to.y != at.y || to.z != at.z;
    mask[a] = actions[a] == "stay" || changes;
    moves = moves || changes;
  }
  if (!moves)
    return {};
  return mask;
}

double UavPositioningEnv::RewardOf(const StepInfo& info) const {
  return (*reward_)(RewardInputOf(scenario_, info.n_los, info.throughput_mbps, info.demands_met));
}

void UavPositioningEnv::Observe() {
  StepInfo& info = info_;
  if (analytic_) {
    analytic_->EvaluateInto(placement_, info);  // reuses info_'s vectors on a memo hit
  } else {
    info = StepInfo{};
    const RunMetrics m = network_->Measure();
    info.positions = placement_;
    info.serving = network_->Association();
    info.n_los = m.n_los;
    info.throughput_mbps = m.aggregate_throughput_mbps;
    info.demands_met = m.demands_met;
    for (const auto& ue : m.ues) {
      info.snr_db.push_back(ue.snr_db);
      info.los.push_back(ue.los ? 1 : 0);
    }
  }
  info.active_uav = static_cast<int>(active_);
  if (model_observations_)
    FillModelObservations(active_, info);
}

std::vector<double> UavPositioningEnv::Reset(std::uint64_t seed) {
  return Reset(seed, ResetOptions{});
}

std::vector<double> UavPositioningEnv::Reset(std::uint64_t seed, const ResetOptions& options) {
  placement_ = options.random_start ? RandomStart(scenario_, buildings_, seed)
                                    : scenario_.InitialPlacement();
  active_ = 0;
  steps_ = 0;
  if (!analytic_) {
    // A fresh network per episode: RngRun = seed; traffic lasts the whole episode.
    Scenario episode = scenario_;
    episode.simulation.run = seed;
    const double dt = scenario_.env.decision_interval;
    const double warmup = std::max(scenario_.simulation.warmup, dt);
    episode.simulation.warmup = warmup;
    episode.simulation.duration = warmup + scenario_.env.episode_duration + dt;
    network_.reset();  // one ns-3 simulation at a time
    // UEs associate at the initial placement; each step re-associates them (MoveTo).
    network_ = std::make_unique<UavNetwork>(episode, placement_,
                                            HandsOver() ? Handover::kOn : Handover::kOff);
    network_->BeginMeasurement({warmup - dt, warmup});
    network_->RunUntil(warmup);
  }
  Observe();
  KeepBest(true);
  return MakeObservation(scenario_, info_);
}

double UavPositioningEnv::KeepBest(bool first) {
  const double here = RewardOf(info_);
  best_reward_ = first ? here : std::max(best_reward_, here);
  info_.below_best = best_reward_ - here;
  return here;
}

StepResult UavPositioningEnv::Step(int action) {
  if (!ActionSpace().Contains(action)) {
    throw std::out_of_range(Continuous() ? "this env takes a continuous action (a displacement)"
                                         : "action " + std::to_string(action) +
                                               " out of the action space Discrete(" +
                                               std::to_string(ActionSpace().n) + ")");
  }
  return MoveTo(ApplyDisplacement(scenario_, buildings_, active_, DisplacementOf(active_, action),
                                  placement_));
}

StepResult UavPositioningEnv::StepContinuous(const std::vector<double>& d) {
  if (!Continuous())
    throw std::out_of_range("this env takes discrete actions (move indices)");
  const double step = scenario_.env.step;  // the Box is [-step, step]^3; NaN is outside
  const auto within = [step](double v) { return v >= -step && v <= step; };
  if (d.size() != 3 || !std::all_of(d.begin(), d.end(), within)) {
    const std::string bound = FormatNumber(step);
    throw std::out_of_range("the displacement must have 3 components, each within [-" + bound +
                            ", " + bound + "] m");
  }
  return MoveTo(ApplyDisplacement(scenario_, buildings_, active_, {d[0], d[1], d[2]}, placement_));
}

StepResult UavPositioningEnv::MoveTo(const Placement& placement) {
  placement_ = placement;
  active_ = static_cast<std::size_t>((steps_ + 1) / scenario_.env.turn_steps) % placement_.size();
  if (network_) {
    network_->SetUavPositions(placement_);
    if (HandsOver())
      network_->Reassociate();  // as the analytic model does at every step
    const double now = network_->Now();
    const double next = now + scenario_.env.decision_interval;
    network_->BeginMeasurement({now, next});
    const auto started = std::chrono::steady_clock::now();
    network_->RunUntil(next);
    wall_in_ns3_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  ++steps_;
  Observe();
  StepResult result;
  result.reward = KeepBest(false);
  result.info = info_;
  result.observation = MakeObservation(scenario_, info_);
  result.truncated = steps_ >= steps_per_episode_;
  return result;
}

void UavPositioningEnv::CheckJointStep(std::size_t actions) const {
  if (placement_.empty())
    throw std::logic_error("JointStep before the first Reset");
  if (actions != placement_.size()) {
    throw std::invalid_argument("JointStep: " + std::to_string(actions) + " actions for " +
                                std::to_string(placement_.size()) +
                                " UAVs; expected one per UAV, in the scenario's order");
  }
}

JointStepResult UavPositioningEnv::JointStep(const std::vector<int>& actions) {
  CheckJointStep(actions.size());
  if (Continuous())
    throw std::out_of_range("this env takes continuous actions (displacements)");
  std::vector<Vec3> displacements;
  for (std::size_t u = 0; u < actions.size(); ++u) {
    if (!ActionSpace().Contains(actions[u])) {
      throw std::out_of_range("action " + std::to_string(actions[u]) + " of UAV " +
                              std::to_string(u) + " (\"" + scenario_.uavs[u].name +
                              "\") out of the action space Discrete(" +
                              std::to_string(ActionSpace().n) + ")");
    }
    displacements.push_back(DisplacementOf(u, actions[u]));
  }
  return MoveAllTo(ApplyJointDisplacement(scenario_, buildings_, displacements, placement_));
}

JointStepResult UavPositioningEnv::JointStepContinuous(
    const std::vector<std::vector<double>>& displacements) {
  CheckJointStep(displacements.size());
  if (!Continuous())
    throw std::out_of_range("this env takes discrete actions (move indices)");
  const double step = scenario_.env.step;  // the Box is [-step, step]^3; NaN is outside
  const auto within = [step](double v) { return v >= -step && v <= step; };
  std::vector<Vec3> moves;
  for (std::size_t u = 0; u < displacements.size(); ++u) {
    const auto& d = displacements[u];
    if (d.size() != 3 || !std::all_of(d.begin(), d.end(), within)) {
      const std::string bound = FormatNumber(step);
      throw std::out_of_range(
          "the displacement of UAV " + std::to_string(u) + " (\"" + scenario_.uavs[u].name +
          "\") must have 3 components, each within [-" + bound + ", " + bound + "] m");
    }
    moves.push_back({d[0], d[1], d[2]});
  }
  return MoveAllTo(ApplyJointDisplacement(scenario_, buildings_, moves, placement_));
}

JointStepResult UavPositioningEnv::MoveAllTo(const Placement& placement) {
  StepResult step = MoveTo(placement);
  JointStepResult result;
  result.observations = AgentObservations();
  result.state = State();
  result.reward = step.reward;
  result.terminated = step.terminated;
  result.truncated = step.truncated;
  result.info = std::move(step.info);
  return result;
}

std::vector<std::vector<double>> UavPositioningEnv::AgentObservations() const {
  std::vector<std::vector<double>> observations;
  for (std::size_t u = 0; u < scenario_.uavs.size(); ++u) {
    if (!model_observations_ || u == active_) {
      observations.push_back(AgentObservation(scenario_, info_, u));
      continue;
    }
    StepInfo view = info_;  // each UAV looks around from its own position
    FillModelObservations(u, view);
    observations.push_back(AgentObservation(scenario_, view, u));
  }
  return observations;
}

std::vector<double> UavPositioningEnv::TeamStateOf(std::size_t uav) const {
  return TeamState(scenario_, info_, uav);
}

}  // namespace rlpos
