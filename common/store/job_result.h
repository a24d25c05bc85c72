#pragma once
// What a job's rlpos-sim prints on stdout (--json), checked before it enters the store:
//   train / position: {"position": [x, y, z], ...}
//   eval: rlpos::ToJson(RunMetrics) (common/metrics/run_metrics.h); undefined metrics are null.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>

#include "scenario/scenario.h"

namespace rlpos {

struct EvalResult {
  Vec3 position;
  double aggregate_throughput_mbps = 0;
  std::optional<double> mean_delay_ms, loss_ratio, min_snr_db;
  // Absent from results of builds before schema 9; null when no UE received anything.
  std::optional<double> worst_ue_throughput_mbps, jain_fairness;
  int n_los = 0, n_ues = 0, demands_met = 0;
  std::optional<std::uint64_t> run;
};

// Both throw std::invalid_argument naming the missing or malformed key.
Vec3 ProducedPosition(const nlohmann::json& result);
EvalResult ParseEvalResult(const nlohmann::json& result);

}  // namespace rlpos
