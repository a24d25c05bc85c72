#pragma once
// Line of sight from the building geometry alone, without ns-3: the same rule as the channel
// condition the worker's loss model asks (ns-3's BuildingsChannelConditionModel between two
// outdoor nodes): a link is NLoS when the segment between its ends meets a building's box,
// [xmin, xmax] x [ymin, ymax] x [0, height], boundary included. A test compares the two on
// the shipped scenarios (tests/worker/env/uav_env).
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// True when the closed segment [a, b] meets the closed box.
bool SegmentMeetsBox(const Vec3& a, const Vec3& b, const Box& box);

// True when a building stands between `a` and `b`.
bool LinkBlocked(const std::vector<BuildingSpec>& buildings, const Vec3& a, const Vec3& b);

// The UEs whose links to every UAV of `placement` are blocked: NLoS whichever UAV serves them.
int UesHiddenFromAll(const Scenario& scenario, const Placement& placement);

}  // namespace rlpos
