#include "common/mobility/ue_trajectories.h"

#include <algorithm>

#include "common/mobility/mobility_models.h"
#include "common/mobility/walkable_area.h"

namespace rlpos {
namespace {

UeTrajectory Walk(const Scenario& s, const WalkableArea& area, std::size_t ue, double horizon) {
  const MobilitySpec& m = s.ues[ue].mobility;
  if (m.model == MobilityModel::kStatic)
    return UeTrajectory::Still(s.ues[ue].position);
  TrajectoryBuilder walk(s, area, ue, horizon);
  MobilityRandom random(s.simulation.seed, s.simulation.run, ue);
  switch (m.model) {
    case MobilityModel::kStatic:
      break;
    case MobilityModel::kRandomWalk:
      WalkRandomly(m.random_walk, walk, random);
      break;
    case MobilityModel::kRandomWaypoint:
      WalkRandomWaypoints(m.random_waypoint, walk, random);
      break;
    case MobilityModel::kGaussMarkov:
      WalkGaussMarkov(m.gauss_markov, walk, random);
      break;
    case MobilityModel::kCrowd:
      WalkWithCrowd(m.crowd, walk, random);
      break;
  }
  return std::move(walk).Finish();
}

}  // namespace

double TrajectoryHorizon(const Scenario& scenario) {
  return std::max(scenario.simulation.duration, scenario.env.episode_duration);
}

std::vector<UeTrajectory> UeTrajectories(const Scenario& scenario, double horizon) {
  const WalkableArea area(scenario);
  std::vector<UeTrajectory> out;
  out.reserve(scenario.ues.size());
  for (std::size_t i = 0; i < scenario.ues.size(); ++i)
    out.push_back(Walk(scenario, area, i, horizon));
  return out;
}

std::vector<UeTrajectory> UeTrajectories(const Scenario& scenario) {
  return UeTrajectories(scenario, TrajectoryHorizon(scenario));
}

bool AnyUeMoves(const Scenario& scenario) {
  return std::any_of(scenario.ues.begin(), scenario.ues.end(),
                     [](const UeSpec& ue) { return ue.mobility.model != MobilityModel::kStatic; });
}

}  // namespace rlpos
