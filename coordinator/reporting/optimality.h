#pragma once
// The optimality section of `rlpos-campaign results` and the report: how close each placement
// comes to the oracle's, as the ratio of their rewards (common/store/optimality_rows.h), per
// algorithm (or named policy, or positioner) and number of UAVs: median, 10th percentile, worst,
// the share of runs at or above 95 % of the oracle, and the median seconds per placement. A run
// is one placement: one scenario and algorithm and train seed, or one scenario and named policy
// or positioner. Per-scenario training and a policy for any scenario (zero-shot) sit side by side.
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/stats/empirical_distribution.h"
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
  // Median wall seconds of the jobs that found the placements (NaN: none recorded).
  double median_placement_s = std::numeric_limits<double>::quiet_NaN();
  double NearOptimalShare() const { return runs > 0 ? double(near_optimal_runs) / runs : 0; }
};

// One entry per (algorithm, UAV count) with a ratio: trained algorithms in AllAlgorithms() order
// (an unrecorded one after them), then named policies by name, then the positioners in
// kPositioners order (the oracle's own last); UAV counts ascending. Rows without a ratio (the
// oracle's reward is not positive) are left out; none when no placement but the oracle's has a
// ratio.
std::vector<OptimalitySummary> SummarizeOptimality(const std::vector<OptimalityRow>& rows);

// The rl rows (trained or named, OptimalityRow::IsRl) whose ratio is below kNearOptimalRatio,
// worst first: what to look at.
std::vector<OptimalityRow> RunsBelowNearOptimal(const std::vector<OptimalityRow>& rows);

// The summary as a rounded table for the terminal, as Markdown, as CSV (unrounded) and JSON.
std::string FormatOptimalityText(const std::vector<OptimalitySummary>& summary);
std::string FormatOptimalityMarkdown(const std::vector<OptimalitySummary>& summary);
std::string FormatOptimalitySummaryCsv(const std::vector<OptimalitySummary>& summary);
nlohmann::json OptimalityToJson(const std::vector<OptimalitySummary>& summary);
// Every run: scenario, uavs, algorithm, train_seed, label, runs, rl_reward, oracle_reward, ratio,
// placement_s (rl_reward: the placement's reward, whatever placed it).
std::string FormatOptimalityRowsCsv(const std::vector<OptimalityRow>& rows);
std::string FormatOptimalityRowsMarkdown(const std::vector<OptimalityRow>& rows);
// The empirical CDF of the ratio per (algorithm, UAV count), in the order of SummarizeOptimality;
// the oracle's own (all 1) left out.
struct OptimalityCurve {
  std::string algorithm;
  int uavs = 1;
  std::vector<DistributionPoint> points;  // x: the ratio, p: P(ratio <= x)
};
std::vector<OptimalityCurve> OptimalityCdf(const std::vector<OptimalityRow>& rows);
// Those curves for the plot: algorithm, uavs, ratio, p.
std::string FormatOptimalityCdfCsv(const std::vector<OptimalityRow>& rows);

}  // namespace rlpos
