#include "coordinator/reporting/track_summary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "common/stats/descriptive.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/text_table.h"
#include "coordinator/reporting/track_groups.h"

namespace rlpos {
namespace {

TrackSummary Summarize(const std::vector<const TrackRunRow*>& runs) {
  TrackSummary s;
  s.scenario = runs.front()->scenario;
  s.positioner = runs.front()->label;
  s.fidelity = runs.front()->fidelity;
  s.runs = static_cast<int>(runs.size());
  for (const TrackMetricDef& m : kTrackMetrics) {
    std::vector<double> values;
    for (const TrackRunRow* r : runs) {
      const double v = r->metrics.*(m.field);
      if (std::isfinite(v))
        values.push_back(v);
    }
    s.means.push_back(values.empty() ? std::nullopt : std::optional<double>(Mean(values)));
  }
  return s;
}

// The table's columns: a few of the metrics, those a reader compares first.
struct Shown {
  const char* key;
  const char* title;
  int decimals;
};
constexpr Shown kShown[] = {
    {"mean_reward", "reward", 4},          {"reward_p5", "reward P5", 4},
    {"mean_throughput_mbps", "Mbit/s", 2}, {"throughput_p5_mbps", "Mbit/s P5", 2},
    {"mean_delay_ms", "delay ms", 2},      {"los_share", "LoS", 3},
    {"outage_share", "outage", 3},         {"distance_flown_m", "flown m", 1},
    {"handovers", "handovers", 1}};

std::size_t MetricIndex(const char* key) {
  for (std::size_t i = 0; i < kTrackMetrics.size(); ++i) {
    if (std::string(kTrackMetrics[i].key) == key)
      return i;
  }
  return kTrackMetrics.size();
}

std::vector<TableColumn> TableColumns() {
  std::vector<TableColumn> columns{{"scenario", true}, {"positioner", true}, {"runs", false}};
  for (const Shown& shown : kShown)
    columns.push_back({shown.title, false});
  return columns;
}

std::vector<std::vector<std::string>> TableRows(const std::vector<TrackSummary>& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const TrackSummary& s : summary) {
    std::vector<std::string> row{s.scenario, s.positioner, std::to_string(s.runs)};
    for (const Shown& shown : kShown)
      row.push_back(TableNumber(s.means.at(MetricIndex(shown.key)), shown.decimals));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

std::vector<TrackSummary> SummarizeTracks(const std::vector<TrackRunRow>& rows) {
  const auto groups = GroupTrackRuns(rows);
  std::vector<TrackSummary> out;
  for (const auto& group : groups)
    out.push_back(Summarize(group.second));
  return out;
}

std::string FormatTrackSummaryText(const std::vector<TrackSummary>& summary) {
  return FormatTextTable(TableColumns(), TableRows(summary));
}

std::string FormatTrackSummaryMarkdown(const std::vector<TrackSummary>& summary) {
  if (summary.empty())
    return "";
  return "\n## Track runs\n\n" + FormatMarkdownTable(TableColumns(), TableRows(summary)) +
         "\nRuns in which the UEs walk and the UAVs follow: per scenario and positioner, each "
         "metric's mean over the RngRuns of each run's mean over its scored intervals (P5: the "
         "5th percentile of the intervals, the run's worst moments). Files: `track_summary.csv` "
         "(every metric, unrounded); `track_distributions.csv` and "
         "`track_distributions_<scenario>.png` (over the RngRuns, the CDF of each run's time-mean "
         "reward, delay and outage share, the CCDF of its throughput); `track_series.csv` and "
         "`track_series_<scenario>.png` (each interval averaged over the RngRuns, the warm-up "
         "shaded); per run the view `v_track_runs`, per interval `v_track_intervals`.\n";
}

const std::vector<std::string>& TrackSummaryCsvColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"scenario", "positioner", "fidelity", "runs"};
    for (const TrackMetricDef& m : kTrackMetrics)
      out.push_back(m.key);
    return out;
  }();
  return names;
}

std::string FormatTrackSummaryCsv(const std::vector<TrackSummary>& summary) {
  std::string out = CsvLine(TrackSummaryCsvColumns());
  for (const TrackSummary& s : summary) {
    std::vector<std::string> cells{CsvText(s.scenario), CsvText(s.positioner), CsvText(s.fidelity),
                                   std::to_string(s.runs)};
    for (const auto& mean : s.means)
      cells.push_back(CsvNumber(mean));
    out += CsvLine(cells);
  }
  return out;
}

nlohmann::json TrackSummaryToJson(const std::vector<TrackSummary>& summary) {
  nlohmann::json out = nlohmann::json::array();
  for (const TrackSummary& s : summary) {
    nlohmann::json row = {{"scenario", s.scenario},
                          {"positioner", s.positioner},
                          {"fidelity", s.fidelity},
                          {"runs", s.runs}};
    for (std::size_t i = 0; i < kTrackMetrics.size(); ++i) {
      const auto v = Finite(s.means[i]);
      row[kTrackMetrics[i].key] = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace rlpos
