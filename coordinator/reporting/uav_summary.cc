#include "coordinator/reporting/uav_summary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "common/stats/descriptive.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/run_groups.h"
#include "coordinator/reporting/text_table.h"

namespace rlpos {
namespace {

UavSummary Summarize(const std::vector<const UavMetricRow*>& runs) {
  UavSummary s;
  s.scenario = runs.front()->scenario;
  s.positioner = runs.front()->label;
  s.uav = runs.front()->uav;
  s.name = runs.front()->name;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> served, throughput, delay, nlos, worst, jain;
  for (const UavMetricRow* r : runs) {
    served.push_back(r->ues_served);
    throughput.push_back(r->throughput_mbps.value_or(0));
    nlos.push_back(r->n_los);
    if (r->mean_delay_ms)
      delay.push_back(*r->mean_delay_ms);
    if (r->worst_ue_throughput_mbps)
      worst.push_back(*r->worst_ue_throughput_mbps);
    if (r->jain_fairness)
      jain.push_back(*r->jain_fairness);
  }
  const ConfidenceInterval ci = MeanConfidenceInterval(throughput);
  s.ues_served_mean = Mean(served);
  s.throughput_mean_mbps = ci.mean;
  s.throughput_ci95_mbps = ci.half_width;
  s.nlos_mean = Mean(nlos);
  if (!delay.empty())
    s.delay_mean_ms = Mean(delay);
  if (!worst.empty())
    s.worst_ue_mean_mbps = Mean(worst);
  if (!jain.empty())
    s.jain_mean = Mean(jain);
  return s;
}

const std::vector<TableColumn>& UavTableColumns() {
  static const std::vector<TableColumn> columns{{"scenario", true},     {"positioner", true},
                                                {"uav", true},          {"runs", false},
                                                {"UEs served", false},  {"mean Mbit/s", false},
                                                {"ci95 Mbit/s", false}, {"delay ms", false},
                                                {"nLoS", false},        {"worst UE Mbit/s", false},
                                                {"Jain", false}};
  return columns;
}

std::vector<std::vector<std::string>> TableRows(const std::vector<UavSummary>& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : summary) {
    rows.push_back({s.scenario, s.positioner, s.name, std::to_string(s.runs),
                    TableNumber(s.ues_served_mean, 1), TableNumber(s.throughput_mean_mbps, 2),
                    TableNumber(s.throughput_ci95_mbps, 2), TableNumber(s.delay_mean_ms, 3),
                    TableNumber(s.nlos_mean, 1), TableNumber(s.worst_ue_mean_mbps, 2),
                    TableNumber(s.jain_mean, 3)});
  }
  return rows;
}

// The numeric fields of CSV and JSON, after scenario, positioner, uav, uav_name and runs.
std::vector<std::pair<const char*, std::optional<double>>> Numbers(const UavSummary& s) {
  return {{"ues_served_mean", s.ues_served_mean},
          {"throughput_mean_mbps", s.throughput_mean_mbps},
          {"throughput_ci95_mbps", Finite(s.throughput_ci95_mbps)},
          {"delay_mean_ms", s.delay_mean_ms},
          {"nlos_mean", s.nlos_mean},
          {"worst_ue_mean_mbps", s.worst_ue_mean_mbps},
          {"jain_mean", s.jain_mean}};
}

}  // namespace

std::vector<UavSummary> SummarizeUavs(const std::vector<UavMetricRow>& rows) {
  std::vector<std::string> scenarios;  // those of several UAVs, in order of appearance
  std::set<std::string> several;
  for (const auto& r : rows) {
    if (r.uav > 0)
      several.insert(r.scenario);
  }
  using Key = std::tuple<std::size_t, std::string, int>;  // scenario order, label, uav
  const auto less = [](const Key& a, const Key& b) {
    if (std::get<0>(a) != std::get<0>(b))
      return std::get<0>(a) < std::get<0>(b);
    if (std::get<1>(a) != std::get<1>(b))
      return ReportLabelLess(std::get<1>(a), std::get<1>(b));
    return std::get<2>(a) < std::get<2>(b);
  };
  std::map<Key, std::vector<const UavMetricRow*>, decltype(less)> groups(less);
  for (const auto& r : rows) {
    if (!several.count(r.scenario))
      continue;
    auto found = std::find(scenarios.begin(), scenarios.end(), r.scenario);
    if (found == scenarios.end())
      found = scenarios.insert(scenarios.end(), r.scenario);
    groups[{static_cast<std::size_t>(found - scenarios.begin()), r.label, r.uav}].push_back(&r);
  }
  std::vector<UavSummary> out;
  for (const auto& group : groups)
    out.push_back(Summarize(group.second));
  return out;
}

std::string FormatUavSummaryText(const std::vector<UavSummary>& summary) {
  return FormatTextTable(UavTableColumns(), TableRows(summary));
}

std::string FormatUavSummaryMarkdown(const std::vector<UavSummary>& summary) {
  return FormatMarkdownTable(UavTableColumns(), TableRows(summary));
}

const std::vector<std::string>& UavSummaryCsvColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"scenario", "positioner", "uav", "uav_name", "runs"};
    for (const auto& field : Numbers(UavSummary{}))
      out.push_back(field.first);
    return out;
  }();
  return names;
}

std::string FormatUavSummaryCsv(const std::vector<UavSummary>& summary) {
  std::string out = CsvLine(UavSummaryCsvColumns());
  for (const auto& s : summary) {
    std::vector<std::string> cells{CsvText(s.scenario), CsvText(s.positioner),
                                   std::to_string(s.uav), CsvText(s.name), std::to_string(s.runs)};
    for (const auto& field : Numbers(s))
      cells.push_back(CsvNumber(field.second));
    out += CsvLine(cells);
  }
  return out;
}

nlohmann::json UavSummaryToJson(const std::vector<UavSummary>& summary) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : summary) {
    nlohmann::json row = {{"scenario", s.scenario},
                          {"positioner", s.positioner},
                          {"uav", s.uav},
                          {"uav_name", s.name},
                          {"runs", s.runs}};
    for (const auto& field : Numbers(s)) {
      if (field.second && std::isfinite(*field.second)) {
        row[field.first] = *field.second;
      } else {
        row[field.first] = nullptr;
      }
    }
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
