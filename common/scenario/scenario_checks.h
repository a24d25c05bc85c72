#pragma once
#include "common/scenario/scenario.h"

namespace rlpos {

// Cross-field checks of a parsed scenario: every footprint a valid polygon, everything inside the
// venue, no overlapping buildings (building_checks.h), no UE inside a building, a mobile UE
// starting off every footprint and a crowd's target in the venue and off every footprint, each
// UAV's zone inside the venue and holding its initial position, UAVs apart and uniquely named, a
// UE's fixed UAV one that exists.
// Throws ConfigError naming the JSON path of the offending element.
void CheckScenarioGeometry(const Scenario& scenario);

// Two UAVs at `a` and `b` closer than kMinUavSeparation.
bool UavsOverlap(const Vec3& a, const Vec3& b);
// UAV `uav` at `p` overlaps another UAV of `placement`.
bool OverlapsAnother(const Placement& placement, std::size_t uav, const Vec3& p);

// Index of the first building whose volume holds `p` (boundary included), or -1: its box, or its
// exact footprint between min_height and height.
int BuildingContaining(const Scenario& scenario, const Vec3& p);
// Index of the first building whose ground shape (its box's rectangle or its exact footprint,
// whatever its heights) holds (x, y) (boundary included), or -1.
int FootprintContaining(const Scenario& scenario, double x, double y);

}  // namespace rlpos
