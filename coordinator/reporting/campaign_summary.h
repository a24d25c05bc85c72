#pragma once
// The numbers of `rlpos-campaign results` and of the report's table: per scenario and
// positioner, what the succeeded eval runs say (the paper's tables), computed once here so that
// every output format shows the same values.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct PositionerSummary {
  std::string scenario;
  std::string positioner;  // the eval label: baseline, offset1..5, centroid, oracle, rl, rl@seedN
  int runs = 0;            // succeeded eval runs
  double throughput_median_mbps = 0;  // aggregate throughput over the runs
  double throughput_mean_mbps = 0;
  // Half width of the 95 % confidence interval of the mean (Student t); NaN for one run.
  double throughput_ci95_mbps = std::numeric_limits<double>::quiet_NaN();
  int delay_runs = 0;       // runs with a mean delay
  int delay_null_runs = 0;  // runs that received nothing, so have no delay (left out of it)
  std::optional<double> delay_mean_ms;  // mean over the delay_runs; absent when there are none
  double delay_ci95_ms = std::numeric_limits<double>::quiet_NaN();    // NaN below 2 delay runs
  double nlos_ratio_mean = std::numeric_limits<double>::quiet_NaN();  // mean of n_los / n_ues
  double demands_met_mean = 0;  // mean count of UEs whose demand is met
  double ues_mean = 0;          // mean n_ues (the same in every run of a scenario)
  // Means over the runs that have them (none recorded before schema 9 have).
  std::optional<double> worst_ue_mean_mbps;  // the worst UE's throughput
  std::optional<double> jain_mean;           // Jain's fairness index over the UEs' throughputs
  // Change of the means against the same scenario's "baseline" in %
  // (100 * (value - baseline) / |baseline|): absent when the scenario has no baseline runs (or
  // either side has no delay); NaN when the baseline is 0.
  std::optional<double> throughput_change_pct;
  std::optional<double> delay_change_pct;
};

// One entry per (scenario, label) of `rows`: scenarios in the order of the rows, labels in
// report order (see ReportLabelLess). Empty rows give an empty summary.
std::vector<PositionerSummary> SummarizeRuns(const std::vector<MetricRow>& rows);

// SummarizeRuns over ResultsReader::Metrics. Throws StoreError for an unknown campaign.
std::vector<PositionerSummary> SummarizeCampaign(ResultsReader& store,
                                                 const std::string& campaign_id);

}  // namespace rlpos
