#pragma once
// What a job's rlpos-sim prints on stdout (--json), checked before it enters the store:
//   train / position: {"position": [x, y, z], ...}, and "positions": [[x, y, z], ...] (one per
//     UAV, the first equal to "position") when the scenario has several UAVs
//   eval: rlpos::ToJson(RunMetrics) (common/metrics/run_metrics.h); undefined metrics are null;
//     "uavs" (each UAV's metrics) when the scenario has several.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// One UAV's share of an eval. Null (absent) where the UAV's UEs received nothing or it serves none.
struct UavEvalResult {
  std::string name;
  Vec3 position;
  int ues_served = 0;
  double throughput_mbps = 0;
  std::optional<double> mean_delay_ms, loss_ratio, worst_ue_throughput_mbps, jain_fairness;
  int n_los = 0;
};

struct EvalResult {
  Placement placement;  // one position per UAV
  double aggregate_throughput_mbps = 0;
  std::optional<double> mean_delay_ms, loss_ratio, min_snr_db;
  // Absent from results of builds before schema 9; null when no UE received anything.
  std::optional<double> worst_ue_throughput_mbps, jain_fairness;
  int n_los = 0, n_ues = 0, demands_met = 0;
  std::optional<std::uint64_t> run;
  // One per UAV. A result without "uavs" (one UAV) gives one named "uav" from the totals.
  std::vector<UavEvalResult> uavs;
};

// Equal to a micrometre (relative to the first, for large coordinates): the same position
// printed and read back.
bool SamePosition(const Vec3& a, const Vec3& b);

// Both throw std::invalid_argument naming the missing or malformed key.
Placement ProducedPlacement(const nlohmann::json& result);
EvalResult ParseEvalResult(const nlohmann::json& result);

}  // namespace rlpos
