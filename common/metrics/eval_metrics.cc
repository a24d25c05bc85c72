#include "common/metrics/eval_metrics.h"

namespace rlpos {
namespace {

// "`run`", or "`run` (UAV: `uav`)" when a UAV's differs.
std::string RunAndUav(const std::string& run, const char* uav) {
  if (!uav || run == uav)
    return "`" + run + "`";
  return "`" + run + "` (UAV: `" + uav + "`)";
}

template <typename Def>
std::string SqlColumn(const Def& m) {
  std::string out = RunAndUav(m.key, m.uav_key) + " " + m.SqlType();
  if (!m.nullable)
    out += " NOT NULL";
  if (m.view_column)
    out += std::string(", views: `") + m.view_column + "`";
  return out;
}

}  // namespace

std::string EvalMetricsMarkdown() {
  std::string out =
      "| Metric | Unit | JSON key | SQL column (`metrics`, `uav_metrics`) | Definition |\n"
      "|---|---|---|---|---|\n";
  for (const auto& m : kEvalMetrics) {
    out += std::string("| ") + m.name + " | " + m.unit + " | " + RunAndUav(m.key, m.uav_key) +
           " | " + SqlColumn(m) + " | " + m.doc + " |\n";
  }
  return out;
}

}  // namespace rlpos
