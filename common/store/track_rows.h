#pragma once
// Track runs in the results store (tables track_runs and track_intervals, views v_track_runs and
// v_track_intervals): one row per succeeded track job, its metrics by the columns of
// kTrackMetrics (metrics/track_metrics.h), and one row per interval.
#include <cstdint>
#include <string>
#include <vector>

#include "common/metrics/track_metrics.h"
#include "common/store/metric_rows.h"
#include "common/store/track_result.h"

namespace rlpos {

class Database;

// One succeeded track job (view v_track_runs). mean_delay_ms is NaN where null.
struct TrackRunRow {
  std::string job_id, scenario, label;  // label: the positioner
  std::int64_t rng_run = 0;
  std::string fidelity;
  double duration_s = 0.0, decision_interval_s = 0.0;
  int intervals = 0, scored_intervals = 0;
  TrackMetrics metrics;
};

// One interval of a succeeded track job (view v_track_intervals).
struct TrackIntervalRecord {
  std::string scenario, label;  // label: the positioner
  std::int64_t rng_run = 0;
  int interval = 0;  // its index in the run
  TrackIntervalRow row;
};

// Inserts the run's row and its intervals' (the key's label is the positioner).
void InsertTrackRun(Database& db, const EvalRowKey& key, const TrackRunResult& run);

// One row per succeeded track job, by scenario (campaign order), positioner, rng_run.
std::vector<TrackRunRow> ReadTrackRunRows(Database& db, const std::string& campaign_id);

// Which runs' intervals to read: all of them (the report's time series), or only the lowest
// RngRun of each scenario and positioner (the one run the page's map plays).
enum class TrackRunsRead { kAll, kFirstRunOnly };

// Their intervals, by scenario (campaign order), positioner, rng_run, then interval.
std::vector<TrackIntervalRecord> ReadTrackIntervalRows(Database& db, const std::string& campaign_id,
                                                       TrackRunsRead which);

}  // namespace rlpos
