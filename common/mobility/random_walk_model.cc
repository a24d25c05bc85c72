// random_walk: legs of change_interval s at a constant speed, each in a direction drawn anew.
// A leg that would leave the venue or touch a building is drawn again; after every 100 such
// draws the leg is halved (a UE in a dead end takes shorter steps), and kMaxMobilityDraws
// failures in a row are an error.
#include <cmath>

#include "common/mobility/mobility_models.h"

namespace rlpos {

void WalkRandomly(const RandomWalkSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random) {
  while (!walk.Done()) {
    double length = spec.speed * spec.change_interval;
    bool moved = false;
    for (int draw = 0; draw < kMaxMobilityDraws && !moved; ++draw) {
      if (draw > 0 && draw % 100 == 0)
        length /= 2.0;
      const double a = random.Angle();
      const Vec3 to{walk.position().x + length * std::cos(a),
                    walk.position().y + length * std::sin(a), walk.position().z};
      if (walk.area().LegIsClear(walk.position(), to)) {
        walk.WalkTo(to, spec.speed);
        moved = true;
      }
    }
    if (!moved)
      walk.Fail("no clear direction to walk in " + std::to_string(kMaxMobilityDraws) + " draws");
  }
}

}  // namespace rlpos
