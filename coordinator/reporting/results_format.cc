#include "coordinator/reporting/results_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/text_table.h"

namespace rlpos {
namespace {

// --- Tables (text, Markdown): rounded, "-" for absent ---

const std::vector<TableColumn>& ResultsTableColumns() {
  static const std::vector<TableColumn> columns{
      {"scenario", true},       {"positioner", true},     {"runs", false},
      {"median Mbit/s", false}, {"mean Mbit/s", false},   {"ci95 Mbit/s", false},
      {"delay ms", false},      {"ci95 ms", false},       {"no delay", false},
      {"nLoS/N", false},        {"demands met", false},   {"worst UE Mbit/s", false},
      {"Jain", false},          {"thr vs base %", false}, {"delay vs base %", false}};
  return columns;
}

std::string Compact(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::vector<std::string> TableRow(const PositionerSummary& s) {
  return {s.scenario,
          s.positioner,
          std::to_string(s.runs),
          TableNumber(s.throughput_median_mbps, 2),
          TableNumber(s.throughput_mean_mbps, 2),
          TableNumber(s.throughput_ci95_mbps, 2),
          TableNumber(s.delay_mean_ms, 3),
          TableNumber(s.delay_ci95_ms, 3),
          std::to_string(s.delay_null_runs),
          TableNumber(s.nlos_ratio_mean, 2),
          TableNumber(s.demands_met_mean, 1) + "/" + Compact(s.ues_mean),
          TableNumber(s.worst_ue_mean_mbps, 2),
          TableNumber(s.jain_mean, 3),
          TableNumber(s.throughput_change_pct, 1, true),
          TableNumber(s.delay_change_pct, 1, true)};
}

// --- CSV and JSON: unrounded ---

struct Field {
  const char* name;
  std::optional<double> (*number)(const PositionerSummary&);  // null for text fields
  std::string PositionerSummary::*text = nullptr;             // the text fields
  bool count = false;                                         // an integer in JSON
};

const std::vector<Field>& Fields() {
  using S = PositionerSummary;
  static const std::vector<Field> fields{
      {"scenario", nullptr, &S::scenario},
      {"positioner", nullptr, &S::positioner},
      {"runs", [](const S& s) { return Finite(s.runs); }, nullptr, true},
      {"throughput_median_mbps", [](const S& s) { return Finite(s.throughput_median_mbps); }},
      {"throughput_mean_mbps", [](const S& s) { return Finite(s.throughput_mean_mbps); }},
      {"throughput_ci95_mbps", [](const S& s) { return Finite(s.throughput_ci95_mbps); }},
      {"delay_runs", [](const S& s) { return Finite(s.delay_runs); }, nullptr, true},
      {"delay_null_runs", [](const S& s) { return Finite(s.delay_null_runs); }, nullptr, true},
      {"delay_mean_ms", [](const S& s) { return Finite(s.delay_mean_ms); }},
      {"delay_ci95_ms", [](const S& s) { return Finite(s.delay_ci95_ms); }},
      {"nlos_ratio_mean", [](const S& s) { return Finite(s.nlos_ratio_mean); }},
      {"demands_met_mean", [](const S& s) { return Finite(s.demands_met_mean); }},
      {"ues_mean", [](const S& s) { return Finite(s.ues_mean); }},
      {"worst_ue_mean_mbps", [](const S& s) { return Finite(s.worst_ue_mean_mbps); }},
      {"jain_mean", [](const S& s) { return Finite(s.jain_mean); }},
      {"throughput_change_pct", [](const S& s) { return Finite(s.throughput_change_pct); }},
      {"delay_change_pct", [](const S& s) { return Finite(s.delay_change_pct); }},
  };
  return fields;
}

std::vector<std::vector<std::string>> TableRows(const std::vector<PositionerSummary>& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : summary)
    rows.push_back(TableRow(s));
  return rows;
}

}  // namespace

std::string FormatSummaryText(const std::vector<PositionerSummary>& summary) {
  return FormatTextTable(ResultsTableColumns(), TableRows(summary));
}

std::string FormatSummaryMarkdown(const std::vector<PositionerSummary>& summary) {
  return FormatMarkdownTable(ResultsTableColumns(), TableRows(summary));
}

const std::vector<std::string>& SummaryCsvColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& field : Fields())
      out.push_back(field.name);
    return out;
  }();
  return names;
}

std::string FormatSummaryCsv(const std::vector<PositionerSummary>& summary) {
  std::string out = CsvLine(SummaryCsvColumns());
  for (const auto& s : summary) {
    std::vector<std::string> cells;
    for (const auto& field : Fields()) {
      cells.push_back(field.number ? CsvNumber(field.number(s)) : CsvText(s.*field.text));
    }
    out += CsvLine(cells);
  }
  return out;
}

nlohmann::json SummaryToJson(const std::vector<PositionerSummary>& summary) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : summary) {
    nlohmann::json row = nlohmann::json::object();
    for (const auto& field : Fields()) {
      if (!field.number) {
        row[field.name] = s.*field.text;
        continue;
      }
      const std::optional<double> value = field.number(s);
      if (!value) {
        row[field.name] = nullptr;
      } else if (field.count) {
        row[field.name] = static_cast<long long>(*value);
      } else {
        row[field.name] = *value;
      }
    }
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
