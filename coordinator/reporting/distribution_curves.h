#pragma once
// The data of the paper's Figures 3-7: per scenario and positioner, the CCDF of the aggregate
// throughput and the CDF of the mean delay over the runs, one curve per positioner. Kept as
// plain rows so that the report writes them to CSV and the plotting script draws them.
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct CurvePoint {
  std::string scenario;
  std::string positioner;  // eval label
  double x = 0;            // throughput (Mbit/s) or delay (ms)
  double p = 0;            // CCDF: P(X > x); CDF: P(X <= x)
};

// Scenarios in the order of `rows`, positioners in report order (like the summary), x ascending
// within a curve: one point per distinct value (see EmpiricalCcdf / EmpiricalCdf).
std::vector<CurvePoint> ThroughputCcdf(const std::vector<MetricRow>& rows);
// Runs without a delay (nothing received) are left out; a positioner with none has no curve.
std::vector<CurvePoint> DelayCdf(const std::vector<MetricRow>& rows);

// CSV with header "scenario,positioner,throughput_mbps,p_above" (p = P(X > x)).
std::string FormatThroughputCcdfCsv(const std::vector<CurvePoint>& points);
// CSV with header "scenario,positioner,delay_ms,p_at_most" (p = P(X <= x)).
std::string FormatDelayCdfCsv(const std::vector<CurvePoint>& points);

}  // namespace rlpos
