// gauss_markov (Camp, Boleng, Davies 2002): every `step` s,
//   speed     s = alpha s + (1 - alpha) mean_speed     + sqrt(1 - alpha^2) kSpeedSd x N(0, 1)
//   direction d = alpha d + (1 - alpha) mean_direction + sqrt(1 - alpha^2) kDirectionSd x N(0, 1)
// with the speed kept in [0, 2 mean_speed] and the mean direction drawn once per UE. A step that
// would leave the venue or touch a building is drawn again; from the tenth draw on, the UE turns
// to a fresh mean direction (as the model's edge rule turns it away from the edge), and after
// every 100 draws its step is halved (a UE in a narrow gap takes shorter steps).
#include <algorithm>
#include <cmath>

#include "common/mobility/mobility_models.h"

namespace rlpos {
namespace {

constexpr double kSpeedSdShare = 0.3;               // speed noise: 0.3 x the mean speed (m/s)
constexpr double kDirectionSd = 0.785398163397448;  // direction noise: pi/4 rad

}  // namespace

void WalkGaussMarkov(const GaussMarkovSpec& spec, TrajectoryBuilder& walk, MobilityRandom& random) {
  const double memory = std::sqrt(1.0 - spec.alpha * spec.alpha);
  double mean_direction = random.Angle();
  double speed = spec.speed;
  double direction = mean_direction;
  while (!walk.Done()) {
    bool moved = false;
    double scale = 1.0;
    for (int draw = 0; draw < kMaxMobilityDraws && !moved; ++draw) {
      if (draw >= 10) {
        mean_direction = random.Angle();
        direction = mean_direction;
      }
      if (draw > 0 && draw % 100 == 0)
        scale /= 2.0;
      const double s = std::clamp(spec.alpha * speed + (1.0 - spec.alpha) * spec.speed +
                                      memory * kSpeedSdShare * spec.speed * random.Normal(),
                                  0.0, 2.0 * spec.speed);
      const double d = spec.alpha * direction + (1.0 - spec.alpha) * mean_direction +
                       memory * kDirectionSd * random.Normal();
      const double length = s * spec.step * scale;
      const Vec3 to{walk.position().x + length * std::cos(d),
                    walk.position().y + length * std::sin(d), walk.position().z};
      if (length == 0.0) {
        walk.Wait(spec.step * scale);
      } else if (walk.area().LegIsClear(walk.position(), to)) {
        walk.WalkTo(to, s);
      } else {
        continue;
      }
      speed = s;
      direction = d;
      moved = true;
    }
    if (!moved)
      walk.Fail("no clear step in " + std::to_string(kMaxMobilityDraws) + " draws");
  }
}

}  // namespace rlpos
