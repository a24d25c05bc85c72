#pragma once
// Track runs in the results store (tables track_runs and track_intervals, views v_track_runs and
// v_track_intervals): one row per succeeded track job, its metrics by the columns of
// kTrackMetrics (metrics/track_metrics.h), and one row per interval.
#include <cstdint>
#include <optional>
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

// One interval of a scenario and positioner, averaged over its runs: the report's time series.
// Each value is the mean over the runs that have the interval (delay: those with a delay).
struct TrackSeriesRow {
  std::string scenario, label;
  int interval = 0;
  int runs = 0;
  double time_s = 0.0;  // the interval's end (the same in every run of a scenario)
  bool scored = true;   // in every run
  double reward = 0.0;
  double throughput_mbps = 0.0;
  std::optional<double> delay_ms;
  double los_share = 0.0;
  double demands_met_share = 0.0;
};

// Averaged by SQLite, so that a campaign of many runs is never held in memory: by scenario
// (campaign order), positioner, interval.
std::vector<TrackSeriesRow> ReadTrackSeriesRows(Database& db, const std::string& campaign_id);

}  // namespace rlpos
