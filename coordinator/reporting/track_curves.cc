#include "coordinator/reporting/track_curves.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/stats/empirical_distribution.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/track_groups.h"

namespace rlpos {
namespace {

struct DistributionOf {
  const char* metric;
  bool above;
};
// What an operator asks of a mobile run: how good on the whole, how much it carried, how fast,
// and how often UEs went unserved.
constexpr DistributionOf kDistributions[] = {{"mean_reward", false},
                                             {"mean_throughput_mbps", true},
                                             {"mean_delay_ms", false},
                                             {"outage_share", false}};

double TrackMetrics::*FieldOf(const std::string& key) {
  for (const TrackMetricDef& m : kTrackMetrics) {
    if (key == m.key)
      return m.field;
  }
  return nullptr;
}

}  // namespace

std::vector<TrackCurvePoint> TrackDistributions(const std::vector<TrackRunRow>& rows) {
  const auto groups = GroupTrackRuns(rows);
  std::vector<TrackCurvePoint> out;
  for (const auto& [key, runs] : groups) {
    for (const DistributionOf& d : kDistributions) {
      const auto field = FieldOf(d.metric);
      std::vector<double> sample;
      for (const TrackRunRow* r : runs) {
        const double v = r->metrics.*field;
        if (std::isfinite(v))  // a delay at analytic fidelity has none
          sample.push_back(v);
      }
      if (sample.empty())
        continue;
      for (const auto& point : d.above ? EmpiricalCcdf(sample) : EmpiricalCdf(sample))
        out.push_back(
            {runs.front()->scenario, runs.front()->label, d.metric, d.above, point.x, point.p});
    }
  }
  return out;
}

std::string FormatTrackDistributionsCsv(const std::vector<TrackCurvePoint>& points) {
  std::string out = CsvLine({"scenario", "positioner", "metric", "p_is", "x", "p"});
  for (const TrackCurvePoint& point : points) {
    out += CsvLine({CsvText(point.scenario), CsvText(point.positioner), point.metric,
                    point.above ? "above" : "at_most", CsvNumber(point.x), CsvNumber(point.p)});
  }
  return out;
}

std::vector<TrackSeriesRow> OrderTrackSeries(std::vector<TrackSeriesRow> rows) {
  TrackGroupOrder order;
  std::vector<std::pair<TrackGroupKey, std::size_t>> keys;
  for (std::size_t i = 0; i < rows.size(); ++i)
    keys.emplace_back(order.KeyOf(rows[i].scenario, rows[i].label), i);
  // Stable: the intervals keep their order within a positioner.
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<TrackSeriesRow> out;
  out.reserve(rows.size());
  for (const auto& key : keys)
    out.push_back(std::move(rows[key.second]));
  return out;
}

std::string FormatTrackSeriesCsv(const std::vector<TrackSeriesRow>& rows) {
  std::string out =
      CsvLine({"scenario", "positioner", "interval", "time_s", "runs", "scored", "reward",
               "throughput_mbps", "delay_ms", "los_share", "demands_met_share"});
  for (const TrackSeriesRow& r : rows) {
    out += CsvLine({CsvText(r.scenario), CsvText(r.label), std::to_string(r.interval),
                    CsvNumber(r.time_s), std::to_string(r.runs), r.scored ? "1" : "0",
                    CsvNumber(r.reward), CsvNumber(r.throughput_mbps), CsvNumber(r.delay_ms),
                    CsvNumber(r.los_share), CsvNumber(r.demands_met_share)});
  }
  return out;
}

}  // namespace rlpos
