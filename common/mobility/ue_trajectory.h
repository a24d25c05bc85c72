#pragma once
// One UE's path: piecewise-linear between waypoints with times, which is exact, cheap to
// evaluate, and what ns-3's WaypointMobilityModel plays at packet level.
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

struct Waypoint {
  double time = 0.0;  // s, a whole number of nanoseconds (ns-3's time step)
  Vec3 position;
};

class UeTrajectory {
 public:
  // `waypoints`: at least one, times non-decreasing (std::invalid_argument otherwise).
  explicit UeTrajectory(std::vector<Waypoint> waypoints);
  // A UE that stays at `position`.
  static UeTrajectory Still(const Vec3& position);

  // The position at time `t` (s): the first waypoint's before it, the last one's after it,
  // linear in between.
  Vec3 PositionAt(double t) const;
  const std::vector<Waypoint>& waypoints() const { return waypoints_; }
  // Whether the UE ever leaves its first position.
  bool Moves() const;

 private:
  std::vector<Waypoint> waypoints_;
};

}  // namespace rlpos
