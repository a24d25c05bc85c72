#pragma once
// The metrics of a run in which the UEs walk and the UAVs follow (rlpos-sim track), declared
// once: each one's JSON key in track's output (also its SQL column in track_runs), where it
// lives in TrackMetrics, its plausible range and its doc. From it come: the JSON track prints,
// the check of a track result that comes back to the coordinator, the track_runs columns, the
// columns of `rlpos-campaign results --track`, and the docs' table. The means are over the
// run's scored intervals (at packet level those after the warm-up); P5 over time is the 5th
// percentile of the same intervals' values (R's type 7): how bad the run's worst moments were.
#include <array>
#include <string>

#include "common/metrics/eval_metrics.h"

namespace rlpos {

struct TrackMetrics {
  double mean_reward = 0.0;
  double reward_p5 = 0.0;
  double mean_throughput_mbps = 0.0;
  double throughput_p5_mbps = 0.0;
  double mean_delay_ms = 0.0;  // packet level; NaN at analytic fidelity or when nothing arrived
  double los_share = 0.0;
  double los_share_p5 = 0.0;
  double outage_share = 0.0;
  double demands_met_share_p5 = 0.0;
  double distance_flown_m = 0.0;
  double handovers = 0.0;  // a count
};

struct TrackMetricDef {
  const char* key;
  double TrackMetrics::*field;
  MetricRange range;
  double max;
  bool nullable;
  const char* unit;
  const char* doc;
};

inline constexpr std::array<TrackMetricDef, 11> kTrackMetrics{{
    {"mean_reward", &TrackMetrics::mean_reward, MetricRange::kUpTo, 1e6, false, "env.reward",
     "The env's reward of each interval, averaged over the run"},
    {"reward_p5", &TrackMetrics::reward_p5, MetricRange::kUpTo, 1e6, false, "env.reward",
     "P5 over time of the interval rewards"},
    {"mean_throughput_mbps", &TrackMetrics::mean_throughput_mbps, MetricRange::kUpTo, 1e6, false,
     "Mbit/s",
     "Aggregate throughput of each interval, averaged (analytic: the model's; packet: the bytes "
     "received of the packets sent in the interval)"},
    {"throughput_p5_mbps", &TrackMetrics::throughput_p5_mbps, MetricRange::kUpTo, 1e6, false,
     "Mbit/s", "P5 over time of the interval throughputs"},
    {"mean_delay_ms", &TrackMetrics::mean_delay_ms, MetricRange::kUpTo, 1e9, true, "ms",
     "Packet level: the mean delay of each interval, averaged over the intervals that received "
     "any packet; null at analytic fidelity"},
    {"los_share", &TrackMetrics::los_share, MetricRange::kRatio, 0, false, "ratio",
     "Share of the UE-intervals in LoS of their UAV"},
    {"los_share_p5", &TrackMetrics::los_share_p5, MetricRange::kRatio, 0, false, "ratio",
     "P5 over time of each interval's share of UEs in LoS"},
    {"outage_share", &TrackMetrics::outage_share, MetricRange::kRatio, 0, false, "ratio",
     "Share of the UE-intervals whose demand is not met (SNR below its MCS's)"},
    {"demands_met_share_p5", &TrackMetrics::demands_met_share_p5, MetricRange::kRatio, 0, false,
     "ratio", "P5 over time of each interval's share of UEs whose demand is met"},
    {"distance_flown_m", &TrackMetrics::distance_flown_m, MetricRange::kUpTo, 1e9, false, "m",
     "Distance flown by all the UAVs over the whole run"},
    {"handovers", &TrackMetrics::handovers, MetricRange::kUpTo, 1e9, false, "count",
     "Times a UE's UAV changed from one interval to the next (several UAVs)"},
}};

// The table as Markdown (metric, unit, JSON key and SQL column, doc), for the docs.
std::string TrackMetricsMarkdown();

}  // namespace rlpos
