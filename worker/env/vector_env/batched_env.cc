#include "worker/env/vector_env/batched_env.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/uav_env/shared_placement_memo.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/env/vector_env/thread_pool.h"

namespace rlpos {
namespace {

constexpr std::uint64_t kMaxRun = (std::uint64_t{1} << 63) - 1;  // Python's seeds: int64 >= 0

std::uint64_t RunAfter(std::uint64_t run) {
  return run < kMaxRun ? run + 1 : 0;  // as rlpos.make's env counts runs
}

// Env i's reward and ends, into the arrays the caller asked for.
void WriteOutcome(const BatchBuffers& out, std::size_t i, double reward, bool terminated,
                  bool truncated) {
  if (out.rewards)
    out.rewards[i] = reward;
  if (out.terminated)
    out.terminated[i] = terminated;
  if (out.truncated)
    out.truncated[i] = truncated;
}

std::string Describe(const DiscreteSpace& discrete, const BoxSpace& continuous) {
  if (discrete.n > 0)
    return "Discrete(" + std::to_string(discrete.n) + ")";
  return "a continuous Box of " + std::to_string(continuous.Dim());
}

// One memo per distinct scenario, for memo[i % scenarios.size()]: scenarios of the same content
// (the same file given twice, say) share one, sized for the envs that use it.
std::vector<std::shared_ptr<SharedPlacementMemo>> MemosOf(const std::vector<Scenario>& scenarios,
                                                          std::size_t num_envs) {
  std::map<std::string, std::size_t> first_of;  // content -> first index with it
  std::vector<std::size_t> same_as(scenarios.size());
  std::vector<std::size_t> envs(scenarios.size(), 0);
  for (std::size_t i = 0; i < scenarios.size(); ++i)
    same_as[i] = first_of.emplace(ToJson(scenarios[i]).dump(), i).first->second;
  for (std::size_t e = 0; e < num_envs; ++e)
    ++envs[same_as[e % scenarios.size()]];
  std::vector<std::shared_ptr<SharedPlacementMemo>> memos(scenarios.size());
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    if (same_as[i] == i && envs[i] > 0) {
      memos[i] =
          std::make_shared<SharedPlacementMemo>(scenarios[i].uavs.size(), scenarios[i].ues.size(),
                                                SharedPlacementMemo::BudgetFor(envs[i]));
    }
  }
  for (std::size_t i = 0; i < scenarios.size(); ++i)
    memos[i] = memos[same_as[i]];
  return memos;
}

std::string Label(const std::vector<Scenario>& scenarios, std::size_t i) {
  return "scenario " + std::to_string(i) + " (" + scenarios[i].name + ")";
}

}  // namespace

struct BatchedEnv::Slot {
  Slot(const Scenario& s, std::shared_ptr<SharedPlacementMemo> shared)
      : env(s, shared), memo(std::move(shared)) {}
  UavPositioningEnv env;
  std::shared_ptr<SharedPlacementMemo> memo;
  std::uint64_t next_run = 0;  // the run of its next reset without a seed
  bool ended = false;          // terminated or truncated at the last step: autoreset next
};

BatchedEnv::BatchedEnv(const std::vector<Scenario>& scenarios, const BatchedEnvOptions& options) {
  if (scenarios.empty())
    throw std::invalid_argument("the batched env needs at least one scenario");
  if (options.num_envs < 1 || options.num_envs > kMaxBatchedEnvs) {
    throw std::invalid_argument("num_envs: expected 1 to " + std::to_string(kMaxBatchedEnvs) +
                                ", got " + std::to_string(options.num_envs));
  }
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    if (scenarios[i].env.fidelity != "analytic") {
      throw std::invalid_argument(Label(scenarios, i) +
                                  ": the batched env runs analytic envs only, not " +
                                  scenarios[i].env.fidelity +
                                  " fidelity (ns-3's packet level is one per process: run "
                                  "one process per packet-level env)");
    }
  }
  if (options.seed && *options.seed > kMaxRun - (options.num_envs - 1)) {
    throw std::invalid_argument("seed: seed + num_envs - 1 must be at most 2**63 - 1, got seed " +
                                std::to_string(*options.seed));
  }
  const auto memos = MemosOf(scenarios, options.num_envs);
  slots_.reserve(options.num_envs);
  for (std::size_t i = 0; i < options.num_envs; ++i) {
    const Scenario& s = scenarios[i % scenarios.size()];
    slots_.push_back(std::make_unique<Slot>(s, memos[i % scenarios.size()]));
    const std::uint64_t first = options.seed ? *options.seed : s.agent.seed * 1000000 + 1;
    slots_.back()->next_run = first + i;
  }
  const UavPositioningEnv& first = slots_.front()->env;
  observation_space_ = first.ObservationSpace();
  action_space_ = first.ActionSpace();
  continuous_space_ = first.ContinuousActionSpace();
  uav_count_ = first.scenario().uavs.size();
  for (std::size_t i = 1; i < std::min(scenarios.size(), slots_.size()); ++i) {
    const UavPositioningEnv& env = slots_[i]->env;
    const std::string differ = Label(scenarios, i) + " and " + Label(scenarios, 0) + " differ in ";
    const BoxSpace obs = env.ObservationSpace();
    if (obs.low != observation_space_.low || obs.high != observation_space_.high) {
      throw std::invalid_argument(differ + "their observation space (" + std::to_string(obs.Dim()) +
                                  " against " + std::to_string(ObservationDim()) +
                                  " values, or other bounds): a batch needs one");
    }
    const DiscreteSpace discrete = env.ActionSpace();
    const BoxSpace continuous = env.ContinuousActionSpace();
    if (discrete.n != action_space_.n || continuous.low != continuous_space_.low ||
        continuous.high != continuous_space_.high) {
      throw std::invalid_argument(differ + "their action space (" + Describe(discrete, continuous) +
                                  " against " + Describe(action_space_, continuous_space_) +
                                  ", or other bounds): a batch needs one");
    }
    if (env.scenario().uavs.size() != uav_count_) {
      throw std::invalid_argument(differ + "their number of UAVs (" +
                                  std::to_string(env.scenario().uavs.size()) + " against " +
                                  std::to_string(uav_count_) + "): a batch needs one");
    }
  }
  for (const auto& slot : slots_)
    has_action_mask_ =
        has_action_mask_ || (slot->env.scenario().env.action_mask && action_space_.n > 0);
  observation_clip_ = Float32Clip(observation_space_);
  pool_ = std::make_unique<ThreadPool>(options.threads ? options.threads
                                                       : DefaultThreadCount(slots_.size()));
}

BatchedEnv::~BatchedEnv() = default;

const SharedPlacementMemo& BatchedEnv::MemoOf(std::size_t env) const {
  return *slots_.at(env)->memo;
}

std::size_t BatchedEnv::Threads() const {
  return pool_->Size();
}

const Scenario& BatchedEnv::ScenarioOf(std::size_t env) const {
  return slots_.at(env)->env.scenario();
}

void BatchedEnv::Write(std::size_t i, const std::vector<double>& observation,
                       const BatchBuffers& out) {
  const UavPositioningEnv& env = slots_[i]->env;
  const StepInfo& info = env.LastInfo();
  if (out.raw_observations)
    std::copy(observation.begin(), observation.end(), out.raw_observations + i * ObservationDim());
  if (out.observations) {
    // As rlpos.make's env gives it: float32, clipped to the float32 bounds (NaN stays NaN).
    observation_clip_.Apply(observation, out.observations + i * ObservationDim());
  }
  if (out.n_los)
    out.n_los[i] = info.n_los;
  if (out.throughput_mbps)
    out.throughput_mbps[i] = info.throughput_mbps;
  if (out.demands_met)
    out.demands_met[i] = info.demands_met;
  if (out.positions) {
    double* row = out.positions + i * uav_count_ * 3;
    for (std::size_t u = 0; u < uav_count_; ++u) {
      row[3 * u] = info.positions[u].x;
      row[3 * u + 1] = info.positions[u].y;
      row[3 * u + 2] = info.positions[u].z;
    }
  }
  if (out.active_uav)
    out.active_uav[i] = info.active_uav;
  if (out.action_mask && has_action_mask_) {
    const ActionMask mask = env.ValidActions();
    std::int8_t* row = out.action_mask + i * ActionCount();
    for (std::size_t a = 0; a < ActionCount(); ++a)
      row[a] = mask.empty() ? 1 : static_cast<std::int8_t>(mask[a] != 0);
  }
}

const StepInfo& BatchedEnv::LastInfo(std::size_t env) const {
  return slots_.at(env)->env.LastInfo();
}

void BatchedEnv::Reset(const std::vector<std::optional<std::uint64_t>>& seeds,
                       const ResetOptions& options, const BatchBuffers& out) {
  Reset(seeds, std::vector<ResetOptions>(NumEnvs(), options), out);
}

void BatchedEnv::Reset(const std::vector<std::optional<std::uint64_t>>& seeds,
                       const std::vector<ResetOptions>& options, const BatchBuffers& out) {
  if (options.size() != NumEnvs()) {
    throw std::invalid_argument("reset options: expected one per env (" +
                                std::to_string(NumEnvs()) + "), got " +
                                std::to_string(options.size()));
  }
  if (!seeds.empty() && seeds.size() != NumEnvs()) {
    throw std::invalid_argument("seeds: expected one per env (" + std::to_string(NumEnvs()) +
                                "), got " + std::to_string(seeds.size()));
  }
  pool_->ForEach(NumEnvs(), [&](std::size_t i) {
    Slot& slot = *slots_[i];
    const std::uint64_t run = !seeds.empty() && seeds[i] ? *seeds[i] : slot.next_run;
    slot.next_run = RunAfter(run);
    slot.ended = false;
    Write(i, slot.env.Reset(run, options[i]), out);
  });
  started_ = true;
}

void BatchedEnv::RequireStarted() const {
  if (!started_)
    throw std::logic_error("the batched env must be reset before its first step");
}

template <typename StepOne>
void BatchedEnv::StepEveryEnv(const BatchBuffers& out, StepOne step_one) {
  pool_->ForEach(NumEnvs(), [&](std::size_t i) {
    Slot& slot = *slots_[i];
    if (slot.ended) {  // next-step autoreset: the action is ignored
      const std::uint64_t run = slot.next_run;
      slot.next_run = RunAfter(run);
      slot.ended = false;
      Write(i, slot.env.Reset(run), out);
      WriteOutcome(out, i, 0.0, false, false);
      return;
    }
    const StepResult r = step_one(slot.env, i);
    slot.ended = r.terminated || r.truncated;
    Write(i, r.observation, out);
    WriteOutcome(out, i, r.reward, r.terminated, r.truncated);
  });
}

void BatchedEnv::Step(const std::int64_t* actions, std::size_t count, const BatchBuffers& out) {
  RequireStarted();
  if (action_space_.n == 0)
    throw std::invalid_argument("actions: these envs take continuous actions (displacements)");
  if (count != NumEnvs()) {
    throw std::invalid_argument("actions: expected one move index per env (" +
                                std::to_string(NumEnvs()) + "), got " + std::to_string(count));
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (actions[i] < 0 || actions[i] >= action_space_.n) {
      throw std::invalid_argument(
          "actions[" + std::to_string(i) + "]: expected a move index in [0, " +
          std::to_string(action_space_.n) + "), got " + std::to_string(actions[i]));
    }
  }
  StepEveryEnv(out, [actions](UavPositioningEnv& env, std::size_t i) {
    return env.Step(static_cast<int>(actions[i]));
  });
}

void BatchedEnv::StepContinuous(const double* displacements, std::size_t count,
                                const BatchBuffers& out) {
  RequireStarted();
  const std::size_t dim = continuous_space_.Dim();
  if (dim == 0)
    throw std::invalid_argument("actions: these envs take discrete actions (move indices)");
  if (count != NumEnvs() * dim) {
    throw std::invalid_argument("actions: expected " + std::to_string(NumEnvs()) + " x " +
                                std::to_string(dim) + " displacement components, got " +
                                std::to_string(count));
  }
  for (std::size_t k = 0; k < count; ++k) {
    const double v = displacements[k];
    const std::size_t c = k % dim;
    if (!(v >= continuous_space_.low[c] && v <= continuous_space_.high[c])) {  // NaN too
      throw std::invalid_argument("actions[" + std::to_string(k / dim) + "][" + std::to_string(c) +
                                  "]: expected within [" + FormatNumber(continuous_space_.low[c]) +
                                  ", " + FormatNumber(continuous_space_.high[c]) + "] m, got " +
                                  FormatNumber(v));
    }
  }
  StepEveryEnv(out, [displacements, dim](UavPositioningEnv& env, std::size_t i) {
    return env.StepContinuous(
        std::vector<double>(displacements + i * dim, displacements + (i + 1) * dim));
  });
}

}  // namespace rlpos
