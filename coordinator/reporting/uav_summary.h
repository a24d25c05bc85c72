#pragma once
// Per UAV of the scenarios with several: what each UAV's share of the succeeded eval runs says
// (ResultsReader::UavMetrics, view v_eval_uavs), for `rlpos-campaign results` and the report.
// Single-UAV scenarios are left out: their one UAV is the summary's row.
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct UavSummary {
  std::string scenario, positioner;  // positioner: the eval label
  int uav = 0;                       // index in the scenario's order
  std::string name;
  int runs = 0;
  double ues_served_mean = 0;
  double throughput_mean_mbps = 0;
  // Half width of the 95 % confidence interval of the mean (Student t); NaN for one run.
  double throughput_ci95_mbps = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> delay_mean_ms;  // over the runs in which its UEs received packets
  double nlos_mean = 0;                 // UEs in line of sight of it
  // Over the runs in which it served a UE.
  std::optional<double> worst_ue_mean_mbps, jain_mean;
};

// Scenarios in the order of `rows`, positioners in report order, UAVs in scenario order.
std::vector<UavSummary> SummarizeUavs(const std::vector<UavMetricRow>& rows);

// As results_format.h does for the summary: a rounded table ("-" for absent), Markdown, CSV
// (header UavSummaryCsvColumns(), unrounded, empty for absent) and JSON (null for absent).
std::string FormatUavSummaryText(const std::vector<UavSummary>& summary);
std::string FormatUavSummaryMarkdown(const std::vector<UavSummary>& summary);
std::string FormatUavSummaryCsv(const std::vector<UavSummary>& summary);
const std::vector<std::string>& UavSummaryCsvColumns();
nlohmann::json UavSummaryToJson(const std::vector<UavSummary>& summary);

}  // namespace rlpos
