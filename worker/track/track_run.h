#pragma once
// A run in which the UEs walk their trajectories (common/mobility, the packet level's) and the
// UAVs follow a positioner within their speed limits, scored by the analytic model.
//
// Time advances in decision intervals of env.decision_interval. The UAVs start at the
// positioner's placement for t = 0 (deployed before the run). At each decision t_i the
// positioner sees the UEs where they are and gives targets; each UAV flies toward its target
// for one interval (uav_flight.h); the interval is scored at its end t_i + interval, with the
// UAVs and the UEs where they are then, by the env's reward (env.reward).
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/track/track_positioner.h"

namespace rlpos {

// One interval, scored at its end.
struct TrackInterval {
  double time = 0.0;  // s, the end of the interval
  double reward = 0.0;
  double throughput_mbps = 0.0;
  int n_los = 0;
  int demands_met = 0;
  Placement positions;       // the UAVs, at the end
  Placement targets;         // where the positioner sent them at the interval's start
  std::vector<int> serving;  // per UE: its UAV
};

struct TrackUavSummary {
  double distance_flown_m = 0.0;
  double mean_ues_served = 0.0;  // UEs associated with it, averaged over the intervals
  double los_share = 0.0;        // of the UE-intervals it served: in LoS (0 if it served none)
  double outage_share = 0.0;     // of the UE-intervals it served: demand not met
};

struct TrackResult {
  std::vector<TrackInterval> intervals;
  double mean_reward = 0.0;
  double mean_throughput_mbps = 0.0;
  double los_share = 0.0;         // of all UE-intervals
  double outage_share = 0.0;      // of all UE-intervals: demand not met
  double distance_flown_m = 0.0;  // all UAVs
  std::vector<TrackUavSummary> uavs;
};

// `duration` s of `scenario` (its simulation.run seeds the trajectories, drawn as the packet
// level draws them for simulation.duration = duration): duration / env.decision_interval
// intervals, rounded down. Throws ConfigError at "--duration" when not one interval fits.
TrackResult RunTrack(const Scenario& scenario, TrackPositioner& positioner, double duration);

}  // namespace rlpos
