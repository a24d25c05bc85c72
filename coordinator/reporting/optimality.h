#pragma once
// The optimality section of `rlpos-campaign results` and the report: how close rl's placements
// come to the oracle's, as the ratio of their rewards (common/store/optimality_rows.h), per
// algorithm and number of UAVs: median, 10th percentile, worst, and the share of runs at or above
// 95 % of the oracle. A run is one rl placement: one scenario, algorithm and train seed.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/store/optimality_rows.h"

namespace rlpos {

// A run at or above this share of the oracle's reward is near-optimal.
constexpr double kNearOptimalRatio = 0.95;

struct OptimalitySummary {
  std::string algorithm;  // "" when the train jobs did not record it
  int uavs = 1;
  int runs = 0;       // rl placements with a ratio
  int scenarios = 0;  // distinct scenarios among them
  double median = std::numeric_limits<double>::quiet_NaN();
  double p10 = std::numeric_limits<double>::quiet_NaN();  // 10th percentile (stats Quantile)
  double worst = std::numeric_limits<double>::quiet_NaN();
  int near_optimal_runs = 0;  // ratio >= kNearOptimalRatio
  double NearOptimalShare() const { return runs > 0 ? double(near_optimal_runs) / runs : 0; }
};

// One entry per (algorithm, UAV count) with a ratio: algorithms in AllAlgorithms() order (others
// after, by name), UAV counts ascending. Rows without a ratio (the oracle's reward is not
// positive) are left out.
std::vector<OptimalitySummary> SummarizeOptimality(const std::vector<OptimalityRow>& rows);

// The rows whose ratio is below kNearOptimalRatio, worst first: what to look at.
std::vector<OptimalityRow> RunsBelowNearOptimal(const std::vector<OptimalityRow>& rows);

// The summary as a rounded table for the terminal, as Markdown, as CSV (unrounded) and JSON.
std::string FormatOptimalityText(const std::vector<OptimalitySummary>& summary);
std::string FormatOptimalityMarkdown(const std::vector<OptimalitySummary>& summary);
std::string FormatOptimalitySummaryCsv(const std::vector<OptimalitySummary>& summary);
nlohmann::json OptimalityToJson(const std::vector<OptimalitySummary>& summary);
// Every run: scenario, uavs, algorithm, train_seed, label, runs, rl_reward, oracle_reward, ratio.
std::string FormatOptimalityRowsCsv(const std::vector<OptimalityRow>& rows);
std::string FormatOptimalityRowsMarkdown(const std::vector<OptimalityRow>& rows);
// The empirical CDF of the ratio per (algorithm, UAV count), for the plot: algorithm, uavs,
// ratio, p (P(ratio <= x)), in the order of SummarizeOptimality.
std::string FormatOptimalityCdfCsv(const std::vector<OptimalityRow>& rows);

}  // namespace rlpos
