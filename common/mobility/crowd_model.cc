// crowd: wait until `start`, walk to a spot drawn in the disc of `radius` around the target
// (round buildings when the straight way is blocked), stay `dwell` s, then walk to a spot drawn
// in the whole venue and stay there. UEs with the same settings gather at the same place and
// time, each on its own path.
#include <sstream>
#include <string>

#include "common/mobility/mobility_models.h"

namespace rlpos {
namespace {

// Spots tried, each with its own route search (kMaxMobilityDraws draws per corner).
constexpr int kMaxCrowdSpots = 20;

void WalkSomewhere(TrajectoryBuilder& walk, MobilityRandom& random, const Vec3& center,
                   std::optional<double> radius, double speed, const std::string& where) {
  for (int draw = 0; draw < kMaxCrowdSpots; ++draw) {
    const auto spot = walk.DrawSpot(random, center, radius);
    if (!spot)
      break;
    if (const auto route = walk.FindRoute(random, *spot)) {
      walk.WalkRoute(*route, speed);
      return;
    }
  }
  walk.Fail("no way round the buildings to " + where);
}

}  // namespace

void WalkWithCrowd(const CrowdSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random) {
  walk.Wait(spec.start);
  if (walk.Done())
    return;
  std::ostringstream gathering;
  gathering << "a spot within " << spec.radius << " m of the crowd's target";
  WalkSomewhere(walk, random, spec.target, spec.radius, spec.speed, gathering.str());
  walk.Wait(spec.dwell);
  if (walk.Done())
    return;
  WalkSomewhere(walk, random, walk.position(), std::nullopt, spec.speed, "a spot to disperse to");
}

}  // namespace rlpos
