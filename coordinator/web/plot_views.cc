#include "coordinator/web/plot_views.h"

#include <map>

#include "common/metrics/eval_metrics.h"
#include "common/stats/empirical_distribution.h"
#include "coordinator/reporting/distribution_curves.h"
#include "coordinator/reporting/learning_curves.h"
#include "coordinator/reporting/run_groups.h"

namespace rlpos::web {
namespace {

using nlohmann::json;
using MetricTableEntry = MetricDef<std::optional<double>>;

const MetricTableEntry& FindMetric(const std::string& key) {
  static const auto table = EvalMetricTable<std::optional<double>>();
  for (const auto& def : table) {
    if (key == def.key)
      return def;
  }
  throw std::invalid_argument("unknown metric " + key);
}

std::optional<double> ValueOf(const MetricRow& row, const MetricTableEntry& def) {
  if (def.run_real)
    return row.*def.run_real;
  return static_cast<double>(row.*def.run_count);
}

// The reporting layer's curves where it has them (the report's throughput CCDF and delay CDF),
// the same empirical distributions over the other metrics.
std::vector<CurvePoint> Curves(const std::vector<MetricRow>& rows, const MetricTableEntry& def,
                               bool ccdf) {
  const std::string key = def.key;
  if (key == "aggregate_throughput_mbps" && ccdf)
    return ThroughputCcdf(rows);
  if (key == "mean_delay_ms" && !ccdf)
    return DelayCdf(rows);
  std::vector<CurvePoint> out;
  for (const RunGroup& group : GroupRuns(rows)) {
    std::vector<double> sample;
    for (const MetricRow* run : group.runs) {
      if (const auto value = ValueOf(*run, def))
        sample.push_back(*value);
    }
    if (sample.empty())
      continue;
    for (const auto& point : ccdf ? EmpiricalCcdf(sample) : EmpiricalCdf(sample))
      out.push_back({group.scenario, group.label, point.x, point.p});
  }
  return out;
}

// Consecutive points of the same scenario and positioner as one curve.
json CurvesJson(const std::vector<CurvePoint>& points) {
  json curves = json::array();
  std::size_t begin = 0;
  while (begin < points.size()) {
    std::size_t end = begin;
    while (end < points.size() && points[end].scenario == points[begin].scenario &&
           points[end].positioner == points[begin].positioner)
      ++end;
    json x = json::array(), p = json::array();
    for (std::size_t i : ThinnedIndices(end - begin, kMaxCurvePoints)) {
      x.push_back(points[begin + i].x);
      p.push_back(points[begin + i].p);
    }
    curves.push_back({{"scenario", points[begin].scenario},
                      {"positioner", points[begin].positioner},
                      {"runs", end - begin},
                      {"x", x},
                      {"p", p}});
    begin = end;
  }
  return curves;
}

}  // namespace

std::vector<std::size_t> ThinnedIndices(std::size_t n, std::size_t max) {
  std::vector<std::size_t> out;
  if (n <= max) {
    for (std::size_t i = 0; i < n; ++i)
      out.push_back(i);
    return out;
  }
  for (std::size_t k = 0; k < max; ++k)
    out.push_back(k * (n - 1) / (max - 1));
  return out;
}

json DistributionJson(ResultsReader& store, const std::string& campaign_id,
                      const std::string& metric, const std::string& kind,
                      const std::string& scenario) {
  const MetricTableEntry& def = FindMetric(metric);
  const bool throughput = std::string(def.unit) == "Mbit/s";
  const bool ccdf = kind.empty() ? throughput : kind == "ccdf";
  std::vector<MetricRow> rows = store.Metrics(campaign_id);
  if (!scenario.empty()) {
    std::vector<MetricRow> kept;
    for (auto& row : rows) {
      if (row.scenario == scenario)
        kept.push_back(std::move(row));
    }
    rows = std::move(kept);
  }
  return {{"metric", def.key},
          {"name", def.name},
          {"unit", def.unit},
          {"kind", ccdf ? "ccdf" : "cdf"},
          {"curves", CurvesJson(Curves(rows, def, ccdf))}};
}

json LearningCurvesJson(ResultsReader& store, const std::string& campaign_id,
                        const std::string& scenario) {
  std::vector<std::string> warnings;
  const auto points = ReadLearningCurves(store, campaign_id, warnings);
  // One curve per (scenario, label), in the order of the jobs.
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, std::vector<const LearningCurvePoint*>> curves;
  for (const auto& point : points) {
    if (point.phase != "train" || (!scenario.empty() && point.scenario != scenario))
      continue;
    const auto key = std::make_pair(point.scenario, point.label);
    if (!curves.count(key))
      order.push_back(key);
    curves[key].push_back(&point);
  }
  json out = json::array();
  for (const auto& key : order) {
    const auto& curve = curves[key];
    json episode = json::array(), reward = json::array(), loss = json::array(),
         epsilon = json::array();
    for (std::size_t i : ThinnedIndices(curve.size(), kMaxLearningPoints)) {
      episode.push_back(curve[i]->episode);
      reward.push_back(curve[i]->total_reward);
      loss.push_back(curve[i]->mean_loss);
      epsilon.push_back(curve[i]->epsilon);
    }
    out.push_back({{"scenario", key.first},
                   {"label", key.second},
                   {"episodes", curve.size()},
                   {"episode", episode},
                   {"reward", reward},
                   {"loss", loss},
                   {"epsilon", epsilon}});
  }
  // Warnings name files beside the database: the page shows only how many curves were skipped.
  return {{"curves", out}, {"skipped", warnings.size()}};
}

json DistributionMetricsJson() {
  json out = json::array();
  for (const auto& def : EvalMetricTable<double>()) {
    const bool throughput = std::string(def.unit) == "Mbit/s";
    out.push_back({{"metric", def.key},
                   {"name", def.name},
                   {"unit", def.unit},
                   {"kind", throughput ? "ccdf" : "cdf"}});
  }
  return out;
}

}  // namespace rlpos::web
