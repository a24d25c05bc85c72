#include "coordinator/reporting/optimality.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "common/scenario/names.h"
#include "common/scenario/scenario_parser.h"
#include "common/stats/descriptive.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/text_table.h"

namespace rlpos {
namespace {

// (rank, name, UAVs): the trained algorithms first, in AllAlgorithms() order (an unrecorded
// one after them), then the named policies by name, then the other positioners in kPositioners
// order, the oracle's own placements among them.
using GroupKey = std::tuple<std::size_t, std::string, int>;

std::size_t RankOf(const OptimalityRow& row) {
  const auto& all = AllAlgorithms();
  if (row.trained)
    return static_cast<std::size_t>(std::find(all.begin(), all.end(), row.algorithm) - all.begin());
  if (row.IsRl())
    return all.size() + 1;
  const auto positioner = std::find(kPositioners.begin(), kPositioners.end(), row.label);
  return all.size() + 2 + static_cast<std::size_t>(positioner - kPositioners.begin());
}

GroupKey KeyOf(const OptimalityRow& row) {
  return {RankOf(row), row.algorithm, row.uavs};
}

// The rows with a ratio, per group, in group order.
std::map<GroupKey, std::vector<const OptimalityRow*>> Groups(
    const std::vector<OptimalityRow>& rows) {
  std::map<GroupKey, std::vector<const OptimalityRow*>> groups;
  for (const auto& row : rows) {
    if (row.Ratio())
      groups[KeyOf(row)].push_back(&row);
  }
  return groups;
}

OptimalitySummary Summarize(const std::vector<const OptimalityRow*>& runs) {
  OptimalitySummary s;
  s.algorithm = runs.front()->algorithm;
  s.uavs = runs.front()->uavs;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> ratios;
  std::vector<double> seconds;
  std::set<std::string> scenarios;
  for (const OptimalityRow* run : runs) {
    const double ratio = *run->Ratio();
    ratios.push_back(ratio);
    scenarios.insert(run->scenario);
    s.near_optimal_runs += ratio >= kNearOptimalRatio ? 1 : 0;
    if (run->placement_s)
      seconds.push_back(*run->placement_s);
  }
  s.scenarios = static_cast<int>(scenarios.size());
  s.median = Median(ratios);
  s.p10 = Quantile(ratios, 0.1);
  s.worst = *std::min_element(ratios.begin(), ratios.end());
  if (!seconds.empty())
    s.median_placement_s = Median(seconds);
  return s;
}

std::string AlgorithmText(const std::string& algorithm) {
  return algorithm.empty() ? "-" : algorithm;
}

// Seconds to one decimal below 100 s, whole above; "-" when unknown.
std::string SecondsText(std::optional<double> seconds) {
  if (!seconds || !std::isfinite(*seconds))
    return "-";
  return TableNumber(*seconds, *seconds < 100 ? 1 : 0);
}

const std::vector<TableColumn>& SummaryColumns() {
  static const std::vector<TableColumn> columns{
      {"algorithm", true},  {"UAVs", false},    {"runs", false},
      {"scenarios", false}, {"median", false},  {"P10", false},
      {"worst", false},     {">= 0.95", false}, {"placement s", false}};
  return columns;
}

std::vector<std::vector<std::string>> SummaryRows(const std::vector<OptimalitySummary>& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : summary) {
    rows.push_back({AlgorithmText(s.algorithm), std::to_string(s.uavs), std::to_string(s.runs),
                    std::to_string(s.scenarios), TableNumber(s.median, 3), TableNumber(s.p10, 3),
                    TableNumber(s.worst, 3),
                    std::to_string(s.near_optimal_runs) + "/" + std::to_string(s.runs) + " (" +
                        TableNumber(100.0 * s.NearOptimalShare(), 0) + " %)",
                    SecondsText(s.median_placement_s)});
  }
  return rows;
}

}  // namespace

std::vector<OptimalitySummary> SummarizeOptimality(const std::vector<OptimalityRow>& rows) {
  std::vector<OptimalitySummary> out;
  // The oracle against itself alone compares nothing.
  if (std::none_of(rows.begin(), rows.end(),
                   [](const OptimalityRow& r) { return !r.IsOracle() && r.Ratio(); }))
    return out;
  for (const auto& group : Groups(rows))
    out.push_back(Summarize(group.second));
  return out;
}

std::vector<OptimalityRow> RunsBelowNearOptimal(const std::vector<OptimalityRow>& rows) {
  std::vector<OptimalityRow> out;
  for (const auto& row : rows) {
    if (row.IsRl() && row.Ratio() && *row.Ratio() < kNearOptimalRatio)
      out.push_back(row);
  }
  std::stable_sort(out.begin(), out.end(), [](const OptimalityRow& a, const OptimalityRow& b) {
    return *a.Ratio() < *b.Ratio();
  });
  return out;
}

std::string FormatOptimalityText(const std::vector<OptimalitySummary>& summary) {
  return FormatTextTable(SummaryColumns(), SummaryRows(summary));
}

std::string FormatOptimalityMarkdown(const std::vector<OptimalitySummary>& summary) {
  return FormatMarkdownTable(SummaryColumns(), SummaryRows(summary));
}

std::string FormatOptimalitySummaryCsv(const std::vector<OptimalitySummary>& summary) {
  std::string out = CsvLine({"algorithm", "uavs", "runs", "scenarios", "median", "p10", "worst",
                             "near_optimal_runs", "near_optimal_share", "median_placement_s"});
  for (const auto& s : summary) {
    out += CsvLine({CsvText(s.algorithm), std::to_string(s.uavs), std::to_string(s.runs),
                    std::to_string(s.scenarios), CsvNumber(s.median), CsvNumber(s.p10),
                    CsvNumber(s.worst), std::to_string(s.near_optimal_runs),
                    CsvNumber(s.NearOptimalShare()), CsvNumber(s.median_placement_s)});
  }
  return out;
}

nlohmann::json OptimalityToJson(const std::vector<OptimalitySummary>& summary) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : summary) {
    out.push_back({{"algorithm", s.algorithm},
                   {"uavs", s.uavs},
                   {"runs", s.runs},
                   {"scenarios", s.scenarios},
                   {"median", s.median},
                   {"p10", s.p10},
                   {"worst", s.worst},
                   {"near_optimal_runs", s.near_optimal_runs},
                   {"near_optimal_share", s.NearOptimalShare()},
                   {"median_placement_s", std::isfinite(s.median_placement_s)
                                              ? nlohmann::json(s.median_placement_s)
                                              : nlohmann::json(nullptr)}});
  }
  return out;
}

std::string FormatOptimalityRowsCsv(const std::vector<OptimalityRow>& rows) {
  std::string out = CsvLine({"scenario", "uavs", "algorithm", "train_seed", "label", "runs",
                             "rl_reward", "oracle_reward", "ratio", "placement_s"});
  for (const auto& r : rows) {
    out += CsvLine({CsvText(r.scenario), std::to_string(r.uavs), CsvText(r.algorithm),
                    std::to_string(r.train_seed), CsvText(r.label), std::to_string(r.runs),
                    CsvNumber(r.rl_reward), CsvNumber(r.oracle_reward), CsvNumber(r.Ratio()),
                    CsvNumber(r.placement_s)});
  }
  return out;
}

std::string FormatOptimalityRowsMarkdown(const std::vector<OptimalityRow>& rows) {
  std::vector<std::vector<std::string>> cells;
  for (const auto& r : rows) {
    cells.push_back({r.scenario, std::to_string(r.uavs), AlgorithmText(r.algorithm),
                     std::to_string(r.train_seed), r.label, TableNumber(r.rl_reward, 4),
                     TableNumber(r.oracle_reward, 4), TableNumber(r.Ratio(), 3),
                     SecondsText(r.placement_s)});
  }
  return FormatMarkdownTable({{"scenario", true},
                              {"UAVs", false},
                              {"algorithm", true},
                              {"train seed", false},
                              {"label", true},
                              {"rl reward", false},
                              {"oracle reward", false},
                              {"ratio", false},
                              {"placement s", false}},
                             cells);
}

std::vector<OptimalityCurve> OptimalityCdf(const std::vector<OptimalityRow>& rows) {
  std::vector<OptimalityCurve> out;
  for (const auto& group : Groups(rows)) {
    if (group.second.front()->IsOracle())
      continue;  // the oracle against itself: a step at 1
    std::vector<double> ratios;
    for (const OptimalityRow* row : group.second)
      ratios.push_back(*row->Ratio());
    out.push_back({std::get<1>(group.first), std::get<2>(group.first), EmpiricalCdf(ratios)});
  }
  return out;
}

std::string FormatOptimalityCdfCsv(const std::vector<OptimalityRow>& rows) {
  std::string out = CsvLine({"algorithm", "uavs", "ratio", "p"});
  for (const OptimalityCurve& curve : OptimalityCdf(rows)) {
    for (const DistributionPoint& point : curve.points) {
      out += CsvLine({CsvText(curve.algorithm), std::to_string(curve.uavs), CsvNumber(point.x),
                      CsvNumber(point.p)});
    }
  }
  return out;
}

}  // namespace rlpos
