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

#include "common/metrics/eval_metrics.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// One UAV's share of an eval (UavMetricFields, metrics/eval_metrics.h). Null (absent) where the
// UAV's UEs received nothing or it serves none.
struct UavEvalResult : UavMetricFields<std::optional<double>> {
  std::string name;
  Vec3 position;
};

// The run's metrics (RunMetricFields); a metric newer than the result's build is absent.
struct EvalResult : RunMetricFields<std::optional<double>> {
  Placement placement;  // one position per UAV
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
