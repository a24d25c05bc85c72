#include "coordinator/reporting/distribution_curves.h"

#include "common/stats/empirical_distribution.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/run_groups.h"

namespace rlpos {
namespace {

void AddCurve(const RunGroup& group, const std::vector<DistributionPoint>& curve,
              std::vector<CurvePoint>& out) {
  for (const auto& point : curve)
    out.push_back({group.scenario, group.label, point.x, point.p});
}

std::string FormatCurvesCsv(const std::vector<CurvePoint>& points, const std::string& x_name,
                            const std::string& p_name) {
  std::string out = CsvLine({"scenario", "positioner", x_name, p_name});
  for (const auto& point : points) {
    out += CsvLine({CsvText(point.scenario), CsvText(point.positioner), CsvNumber(point.x),
                    CsvNumber(point.p)});
  }
  return out;
}

}  // namespace

std::vector<CurvePoint> ThroughputCcdf(const std::vector<MetricRow>& rows) {
  std::vector<CurvePoint> out;
  for (const RunGroup& group : GroupRuns(rows)) {
    std::vector<double> sample;
    for (const MetricRow* run : group.runs)
      sample.push_back(run->aggregate_throughput_mbps.value_or(0));
    AddCurve(group, EmpiricalCcdf(sample), out);
  }
  return out;
}

std::vector<CurvePoint> DelayCdf(const std::vector<MetricRow>& rows) {
  std::vector<CurvePoint> out;
  for (const RunGroup& group : GroupRuns(rows)) {
    std::vector<double> sample;
    for (const MetricRow* run : group.runs) {
      if (run->mean_delay_ms)
        sample.push_back(*run->mean_delay_ms);
    }
    if (!sample.empty())
      AddCurve(group, EmpiricalCdf(sample), out);
  }
  return out;
}

std::string FormatThroughputCcdfCsv(const std::vector<CurvePoint>& points) {
  return FormatCurvesCsv(points, "throughput_mbps", "p_above");
}

std::string FormatDelayCdfCsv(const std::vector<CurvePoint>& points) {
  return FormatCurvesCsv(points, "delay_ms", "p_at_most");
}

}  // namespace rlpos
