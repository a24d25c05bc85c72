#pragma once
// How far a UAV gets toward its target in one decision interval: along the straight line, as far
// as both uav.max_speed (horizontal) and uav.max_climb (vertical) allow.
#include <cstddef>

#include "common/scenario/scenario.h"

namespace rlpos {

// UAV `uav` of `now` after flying `seconds` toward `target`, inside its zone. A leg that would
// pass through a building or end within kMinUavSeparation of another UAV of `now` is replaced
// by level flight toward the target, else by a climb, else the UAV holds: an airframe never
// enters a building (it climbs over it) nor another UAV.
Vec3 FlyToward(const Scenario& scenario, std::size_t uav, const Placement& now, const Vec3& target,
               double seconds);

// The seconds the straight leg from `from` to `to` takes at the UAV's limits: the longer of its
// horizontal and its vertical part (both flown at once, as FlyToward's legs are).
double FlightSeconds(const UavSpec& uav, const Vec3& from, const Vec3& to);

}  // namespace rlpos
