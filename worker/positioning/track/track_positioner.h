#pragma once
// The positioners of a run in which the UEs move: each decision gives the UAVs' targets from
// the UEs' positions at that moment. Held positioners (baseline, centroid, oracle) decide once,
// for t = 0, and keep that placement; tracking ones (names.h: kTrackingPositioners) decide anew
// every time.
#include <memory>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

class TrackPositioner {
 public:
  virtual ~TrackPositioner() = default;
  // The UAVs' targets with the UEs at `ue_positions` (one per UE) and the UAVs at `uavs_now`.
  virtual Placement Decide(const std::vector<Vec3>& ue_positions, const Placement& uavs_now) = 0;
};

// `name` of kTrackPositioners for `scenario`. Throws ConfigError at "--positioner" for rl (a
// policy, which the RL module flies: rlpos-sim track --policy), offsets (placed around rl's
// position) and any other name.
// The oracle is the analytic one (no packet-level re-score): a track run at analytic fidelity
// scores every placement with the analytic model.
std::unique_ptr<TrackPositioner> MakeTrackPositioner(const std::string& name,
                                                     const Scenario& scenario);

}  // namespace rlpos
