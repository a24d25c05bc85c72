#pragma once
#include "scenario/scenario.h"

namespace rlpos {

// Cross-field checks of a parsed scenario: everything inside the venue, no overlapping buildings,
// no UE inside a building, the UAV's zone inside the venue and holding its initial position.
// Throws ConfigError naming the JSON path of the offending element.
void CheckScenarioGeometry(const Scenario& scenario);

// Index of the building whose volume holds `p` (boundary included), or -1.
int BuildingContaining(const Scenario& scenario, const Vec3& p);

}  // namespace rlpos
