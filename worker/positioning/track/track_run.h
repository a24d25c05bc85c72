#pragma once
// A run in which the UEs walk their trajectories (common/mobility, the packet level's) and the
// UAVs follow a positioner within their speed limits, scored by the analytic model or by ns-3's
// packets (track_scoring.h).
//
// Time advances in decision intervals of env.decision_interval. The UAVs start at the
// positioner's placement for t = 0 (deployed before the run). At each decision t_i the
// positioner sees the UEs where they are and gives targets; each UAV flies toward its target
// for one interval (uav_flight.h); the interval is scored by the env's reward (env.reward): at
// its end t_i + interval by the analytic model, with the UAVs and the UEs where they are then,
// or over the interval by the packets (throughput and delay measured, LoS and SNR at its end).
#include <vector>

#include "common/metrics/track_metrics.h"
#include "common/scenario/scenario.h"
#include "worker/positioning/track/track_positioner.h"

namespace rlpos {

// One interval, scored at its end.
struct TrackInterval {
  double time = 0.0;   // s, the end of the interval
  bool scored = true;  // false: in the packet level's warm-up, not in the means
  double reward = 0.0;
  double throughput_mbps = 0.0;
  double mean_delay_ms = 0.0;  // packet level (NaN: nothing received); NaN when analytic
  int n_los = 0;
  int demands_met = 0;
  Placement positions;          // the UAVs at the end, as the scoring has them (packet: ns-3's)
  Placement targets;            // where the positioner sent them at the interval's start
  std::vector<int> serving;     // per UE: its UAV
  std::vector<int> los;         // per UE: 1 in LoS of its UAV
  std::vector<int> demand_met;  // per UE: 1 when its SNR carries its demand
};

struct TrackUavSummary {
  double distance_flown_m = 0.0;
  double mean_ues_served = 0.0;  // UEs associated with it, averaged over the intervals
  double los_share = 0.0;        // of the UE-intervals it served: in LoS (0 if it served none)
  double outage_share = 0.0;     // of the UE-intervals it served: demand not met
};

struct TrackResult {
  std::vector<TrackInterval> intervals;
  // Over the scored intervals (common/metrics/track_metrics.h).
  TrackMetrics metrics;
  std::vector<TrackUavSummary> uavs;
};

enum class TrackFidelity { kAnalytic, kPacket };

// `duration` s of `scenario` (its simulation.run seeds the trajectories, drawn as the packet
// level draws them for simulation.duration = duration): duration / env.decision_interval
// intervals, rounded down. Throws ConfigError at "--duration" when not one interval fits, or at
// packet level when no interval starts after simulation.warmup.
TrackResult RunTrack(const Scenario& scenario, TrackPositioner& positioner, double duration,
                     TrackFidelity fidelity = TrackFidelity::kAnalytic);

}  // namespace rlpos
