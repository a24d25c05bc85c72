// random_waypoint: a destination drawn uniformly on the walkable ground, reached in a straight
// leg at a speed uniform in [speed_min, speed_max], then a pause. A destination whose leg
// touches a building is drawn again (so UEs walk the streets they stand in, as pedestrians do).
#include <string>

#include "common/mobility/mobility_models.h"

namespace rlpos {

void WalkRandomWaypoints(const RandomWaypointSpec& spec, TrajectoryBuilder& walk,
                         MobilityRandom& random) {
  while (!walk.Done()) {
    bool moved = false;
    for (int draw = 0; draw < kMaxMobilityDraws && !moved; ++draw) {
      const auto to = walk.DrawSpot(random, walk.position());
      if (to && walk.area().LegIsClear(walk.position(), *to)) {
        walk.WalkTo(*to, random.Uniform(spec.speed_min, spec.speed_max));
        moved = true;
      }
    }
    if (!moved) {
      walk.Fail("no waypoint with a leg clear of the buildings in " +
                std::to_string(kMaxMobilityDraws) + " draws");
    }
    walk.Wait(spec.pause);
  }
}

}  // namespace rlpos
