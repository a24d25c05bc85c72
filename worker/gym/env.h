#pragma once
// The environment interface the agents see (Gymnasium semantics): reset(seed) -> observation;
// step(action) -> observation, reward, terminated, truncated, info.
#include <cstdint>
#include <vector>

#include "gym/spaces.h"
#include "scenario/scenario.h"

namespace rlpos {

struct StepInfo {
  Vec3 position;
  int n_los = 0;
  double throughput_mbps = 0.0;
  int demands_met = 0;
  std::vector<double> snr_db;
};

struct StepResult {
  std::vector<double> observation;
  double reward = 0.0;
  bool terminated = false;  // a terminal state was reached
  bool truncated = false;   // the episode ran out of time
  StepInfo info;
};

class Env {
 public:
  virtual ~Env() = default;
  virtual DiscreteSpace ActionSpace() const = 0;
  virtual BoxSpace ObservationSpace() const = 0;
  virtual std::vector<double> Reset(std::uint64_t seed) = 0;
  virtual StepResult Step(int action) = 0;
  // The info of the state after the last Reset/Step.
  virtual const StepInfo& LastInfo() const = 0;
  // The actions allowed in the current state; empty (the default) allows all.
  virtual ActionMask ValidActions() const { return {}; }
};

}  // namespace rlpos
