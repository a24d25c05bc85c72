#pragma once
// N analytic UAV positioning envs stepped together in one call over a thread pool, with
// Gymnasium's next-step autoreset: when env i ends (terminated or truncated) at step t, its
// action at step t + 1 is ignored, it resets, and step t + 1 returns the reset observation with
// reward 0 and terminated = truncated = false. Results are written into contiguous buffers the
// caller provides (numpy arrays from Python), row i for env i. The envs are independent values,
// so the results do not depend on the number of threads. The envs of one scenario (same content)
// share one memo of analytic states (shared_placement_memo.h, at most 4 MiB a scenario): what
// one env evaluated, the others look up, bit for bit the same.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

class SharedPlacementMemo;
class ThreadPool;
class UavPositioningEnv;

struct BatchedEnvOptions {
  std::size_t num_envs = 1;  // 1 .. kMaxBatchedEnvs
  // Env i's first run (the RngRun of its first reset without a seed): seed + i; without a
  // seed, agent.seed * 1000000 + 1 + i of its scenario (rlpos-sim train's first episode run).
  std::optional<std::uint64_t> seed;
  std::size_t threads = 0;  // 0: min(hardware threads, num_envs)
};

// Where a Reset or Step writes, row-major, one row per env. A null pointer: not wanted.
struct BatchBuffers {
  float* observations = nullptr;        // N x ObservationDim(), clipped to the observation space
  double* raw_observations = nullptr;   // N x ObservationDim(), as the env gives them (C++ agents)
  double* rewards = nullptr;            // N (Step)
  bool* terminated = nullptr;           // N (Step)
  bool* truncated = nullptr;            // N (Step)
  std::int64_t* n_los = nullptr;        // N
  double* throughput_mbps = nullptr;    // N
  std::int64_t* demands_met = nullptr;  // N
  double* positions = nullptr;          // N x UavCount() x 3
  std::int64_t* active_uav = nullptr;   // N: the UAV the next action moves
  std::int8_t* action_mask = nullptr;   // N x ActionCount(): 1 allowed; all 1 where none applies
};

constexpr std::size_t kMaxBatchedEnvs = 4096;

class BatchedEnv {
 public:
  // Env i gets scenarios[i % scenarios.size()]. Throws std::invalid_argument for no scenario, a
  // num_envs outside 1 .. kMaxBatchedEnvs, packet fidelity (ns-3's packet level is one per
  // process), or scenarios whose observation space, action space or UAV count differ (naming
  // them).
  BatchedEnv(const std::vector<Scenario>& scenarios, const BatchedEnvOptions& options);
  ~BatchedEnv();
  BatchedEnv(const BatchedEnv&) = delete;
  BatchedEnv& operator=(const BatchedEnv&) = delete;

  std::size_t NumEnvs() const { return slots_.size(); }
  std::size_t Threads() const;
  const Scenario& ScenarioOf(std::size_t env) const;
  // The memo of analytic states env `env` shares with the other envs of its scenario's content.
  const SharedPlacementMemo& MemoOf(std::size_t env) const;
  // The spaces every env shares.
  BoxSpace ObservationSpace() const { return observation_space_; }
  DiscreteSpace ActionSpace() const { return action_space_; }           // n = 0: continuous
  BoxSpace ContinuousActionSpace() const { return continuous_space_; }  // Dim() = 0: discrete
  std::size_t ObservationDim() const { return observation_space_.Dim(); }
  std::size_t ActionCount() const { return static_cast<std::size_t>(action_space_.n); }
  std::size_t UavCount() const { return uav_count_; }
  // Whether any env masks its discrete actions (env.action_mask).
  bool HasActionMask() const { return has_action_mask_; }

  // Resets every env: env i with run seeds[i], or where that is empty (or `seeds` is empty) its
  // next run (the one after its last). Clears pending autoresets. std::invalid_argument for a
  // `seeds` of another size than NumEnvs().
  void Reset(const std::vector<std::optional<std::uint64_t>>& seeds, const ResetOptions& options,
             const BatchBuffers& out);
  // The same with env i's own options[i] (a training's exploring starts differ per episode).
  // std::invalid_argument for an `options` of another size than NumEnvs().
  void Reset(const std::vector<std::optional<std::uint64_t>>& seeds,
             const std::vector<ResetOptions>& options, const BatchBuffers& out);
  // Env i's info of its last reset or step (until the next Step).
  const StepInfo& LastInfo(std::size_t env) const;
  // One step of every env: `actions` holds NumEnvs() move indices. An env that ended at the
  // last step resets instead (with its next run, without options). std::invalid_argument, with
  // nothing stepped, for a count other than NumEnvs(), an index outside the action space, or a
  // continuous env; std::logic_error before the first Reset.
  void Step(const std::int64_t* actions, std::size_t count, const BatchBuffers& out);
  // The same with NumEnvs() x 3 displacements (continuous envs), each component within
  // [-env.step, env.step].
  void StepContinuous(const double* displacements, std::size_t count, const BatchBuffers& out);

 private:
  struct Slot;
  void Write(std::size_t env, const std::vector<double>& observation, const BatchBuffers& out);
  void RequireStarted() const;
  template <typename StepOne>
  void StepEveryEnv(const BatchBuffers& out, StepOne step_one);

  std::vector<std::unique_ptr<Slot>> slots_;
  std::unique_ptr<ThreadPool> pool_;
  BoxSpace observation_space_;
  Float32Clip observation_clip_{BoxSpace{}};  // as rlpos.make's env gives an observation
  DiscreteSpace action_space_;
  BoxSpace continuous_space_;
  std::size_t uav_count_ = 0;
  bool has_action_mask_ = false;
  bool started_ = false;  // a Reset has run
};

}  // namespace rlpos
