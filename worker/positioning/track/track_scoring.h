#pragma once
// Where a track run (track_run.h) is scored: by the analytic model at each interval's end, or by
// ns-3's packets over the interval while the UAVs fly their legs and the UEs walk.
#include <memory>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// One interval, as the reward and the metrics see it.
struct IntervalScore {
  bool scored = true;  // false: within the packet level's warm-up, left out of the means
  double throughput_mbps = 0.0;
  double mean_delay_ms = 0.0;  // packet level only (NaN: nothing received); NaN when analytic
  int n_los = 0;
  int demands_met = 0;
  std::vector<int> serving;     // per UE: its UAV
  std::vector<int> los;         // per UE: 1 in LoS of its UAV
  std::vector<int> demand_met;  // per UE: 1 when its SNR carries its demand (CheckDemand)
  Placement uavs;               // where the UAVs are at the end, as the scoring has them
};

class TrackScoring {
 public:
  virtual ~TrackScoring() = default;
  // The UEs' positions at time `t` (s), what a decision at `t` sees. `t` never goes back.
  virtual std::vector<Vec3> UePositionsAt(double t) = 0;
  // Over [start, end] each UAV u flies its straight leg from `from[u]` to `to[u]` (within its
  // speed limits: uav_flight.h), then holds; the interval's score.
  virtual IntervalScore FlyInterval(const Placement& from, const Placement& to, double start,
                                    double end) = 0;
};

// `scenario` with simulation.duration set to the run's: the trajectories' horizon.
std::unique_ptr<TrackScoring> MakeAnalyticScoring(const Scenario& scenario);
// One ns-3 network for the whole run, its UAVs deployed at `start` (a handover-capable one for
// several UAVs: each decision re-applies the association rule). Intervals that start before
// simulation.warmup (association, ARP) are flown but not scored. One per process at a time, as
// every packet-level network.
std::unique_ptr<TrackScoring> MakePacketScoring(const Scenario& scenario, const Placement& start);

}  // namespace rlpos
