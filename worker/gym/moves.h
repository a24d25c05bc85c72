#pragma once
// The UAV's discrete moves and the observation vector, from the scenario's env section.
#include <string>
#include <vector>

#include "gym/env.h"
#include "gym/spaces.h"
#include "scenario/scenario.h"

namespace rlpos {

// The position after `action` (an index into scenario.env.actions): one step in its direction,
// clamped to the UAV's zone. A move that would end inside a building leaves the UAV where it is.
// (With env.action_mask the agent never picks a move that leaves it where it is.)
Vec3 ApplyMove(const Scenario& scenario, int action, const Vec3& from);
// The position after a displacement (env.action_space "continuous"), with the same rules.
Vec3 ApplyDisplacement(const Scenario& scenario, const Vec3& displacement, const Vec3& from);
// The continuous action space: a displacement in metres, each component in [-step, step].
BoxSpace DisplacementBounds(const Scenario& scenario);

// Observation layout and bounds from scenario.env.observations ("snr" expands to one per UE).
BoxSpace ObservationBounds(const Scenario& scenario);
std::vector<double> MakeObservation(const Scenario& scenario, const StepInfo& info);

}  // namespace rlpos
