#pragma once
// The data of the page's plots (JSON): per scenario and positioner, the CCDF or CDF of a metric
// over the runs, and the learning curves of the train jobs. Curves longer than the bounds below
// are thinned evenly (their first and last points kept), so a 100k-run campaign stays a small
// response.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos::web {

constexpr std::size_t kMaxCurvePoints = 1000;
constexpr std::size_t kMaxLearningPoints = 2000;

// {"metric", "name", "unit", "kind", "curves": [{"scenario", "positioner", "x": [...], "p":
// [...]}]}. kind "" takes the metric's default: ccdf for throughputs, cdf otherwise. Runs without
// the metric (null) are left out. `scenario` "" is every scenario.
nlohmann::json DistributionJson(ResultsReader& store, const std::string& campaign_id,
                                const std::string& metric, const std::string& kind,
                                const std::string& scenario);

// {"curves": [{"scenario", "label", "episode": [...], "reward": [...], "loss": [...],
// "epsilon": [...]}], "warnings": [...]}: the train phase of each train job's curve.
nlohmann::json LearningCurvesJson(ResultsReader& store, const std::string& campaign_id,
                                  const std::string& scenario);

// Indices 0..n-1 thinned to at most `max` (max >= 2), evenly, first and last kept.
std::vector<std::size_t> ThinnedIndices(std::size_t n, std::size_t max);

// The metric keys a distribution can be asked for, with their names and units.
nlohmann::json DistributionMetricsJson();

}  // namespace rlpos::web
