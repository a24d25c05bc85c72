#pragma once
// What a track job's rlpos-sim prints (track --json), checked before it enters the store: the
// run's settings, its metrics (common/metrics/track_metrics.h: every key of kTrackMetrics, each
// in its range; mean_delay_ms null where undefined) and its series of intervals, which must add
// up to the metrics. Parsing throws std::invalid_argument naming the key and the problem.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/metrics/track_metrics.h"
#include "common/scenario/scenario.h"

namespace rlpos {

struct TrackIntervalRow {
  double time_s = 0.0;  // the interval's end
  bool scored = true;
  double reward = 0.0;
  double throughput_mbps = 0.0;
  std::optional<double> delay_ms;  // packet level, when a packet arrived
  double los_share = 0.0;
  double demands_met_share = 0.0;
  Placement positions;  // the UAVs at the end
};

struct TrackRunResult {
  std::string positioner;
  std::string fidelity;
  std::uint64_t run = 0;
  double duration_s = 0.0;
  double decision_interval_s = 0.0;
  int scored_intervals = 0;
  TrackMetrics metrics;  // mean_delay_ms NaN when null
  std::vector<TrackIntervalRow> intervals;
};

TrackRunResult ParseTrackResult(const nlohmann::json& result);

}  // namespace rlpos
