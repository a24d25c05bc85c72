#pragma once
// The schema migrations that add the columns of eval metrics declared after schema 10
// (EvalMetricTable(), metrics/eval_metrics.h): a metric's .Since(version) makes that version
// add its column to metrics (and uav_metrics) and to the views v_eval_runs (and v_eval_uavs).
#include <string>
#include <vector>

#include "common/store/schema.h"

namespace rlpos {

// The last schema version written by hand (store/schema.cc) before the metrics' own.
constexpr int kLastHandWrittenSchema = 10;
// Versions written by hand after it (store/schema.cc): a metric's version skips them.
constexpr int kHandWrittenSchemasAfterMetrics[] = {12, 13};

// A metric's new columns; the uav_* are empty for a metric of the run only.
struct MetricColumn {
  std::string type;  // REAL | INTEGER (nullable: rows recorded before have none)
  std::string run_column, run_view;
  std::string uav_column, uav_view;
};

// A migration to `version` that adds `columns`, at the end of the tables and views.
Migration AddMetricColumns(int version, std::vector<MetricColumn> columns);

// One migration per schema version after kLastHandWrittenSchema that the table's metrics name.
// Throws std::logic_error when those versions do not follow each other.
std::vector<Migration> DerivedMetricMigrations();

}  // namespace rlpos
