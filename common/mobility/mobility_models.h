#pragma once
// The mobility models, one file each: each walks its UE from the builder's start until the
// horizon, drawing from the UE's own stream (docs/scenarios.md, "UE mobility").
#include "common/mobility/mobility_random.h"
#include "common/mobility/trajectory_builder.h"

namespace rlpos {

void WalkRandomly(const RandomWalkSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random);
void WalkRandomWaypoints(const RandomWaypointSpec& spec, TrajectoryBuilder& walk,
                         MobilityRandom& random);
void WalkGaussMarkov(const GaussMarkovSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random);
void WalkWithCrowd(const CrowdSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random);

}  // namespace rlpos
