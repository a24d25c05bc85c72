#pragma once
// The "analytic" fidelity: the state at a UAV position without packets. LoS from the building
// geometry and SNR from the very loss-model objects the packet-level channel uses; the MCS per
// UE from ns-3's own rate thresholds; throughput from the airtime-share model.
// Holds a UavNetwork that is built but never run: only one UavNetwork may exist at a time.
#include <memory>

#include "gym/env.h"
#include "scenario/scenario.h"

namespace rlpos {

class UavNetwork;

class AnalyticEvaluator {
 public:
  explicit AnalyticEvaluator(const Scenario& scenario);
  ~AnalyticEvaluator();
  StepInfo Evaluate(const Vec3& position);
  // Per-UE estimated throughput of the last Evaluate (Mbit/s).
  const std::vector<double>& UeThroughput() const { return ue_throughput_; }

 private:
  Scenario scenario_;
  std::unique_ptr<UavNetwork> network_;
  std::vector<double> thresholds_db_;
  std::vector<double> ue_throughput_;
};

}  // namespace rlpos
