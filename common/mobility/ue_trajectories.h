#pragma once
// Every UE's trajectory, a value of (scenario, seed, RngRun): the same at analytic and packet
// fidelity, and the same on every call.
#include <vector>

#include "common/mobility/ue_trajectory.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// How long trajectories are drawn for: the longer of simulation.duration and
// env.episode_duration (a UE stays at its last position after it).
double TrajectoryHorizon(const Scenario& scenario);

// Every UE's trajectory over [0, horizon], in the order of scenario.ues: UE `ue`'s seeded by
// simulation.seed, simulation.run and `ue`. A static UE stays at its position. Throws
// ConfigError at /ues/<ue>/mobility, naming the UE, when the buildings leave it no way to walk
// (kMaxMobilityDraws draws).
std::vector<UeTrajectory> UeTrajectories(const Scenario& scenario, double horizon);
std::vector<UeTrajectory> UeTrajectories(const Scenario& scenario);

// Whether any UE moves (a static scenario keeps today's constant positions).
bool AnyUeMoves(const Scenario& scenario);

}  // namespace rlpos
