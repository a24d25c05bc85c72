#include "common/mobility/mobility_text.h"

#include <sstream>

namespace rlpos {

std::string DescribeMobility(const MobilitySpec& m) {
  std::ostringstream out;
  out << MobilityModelName(m.model);
  switch (m.model) {
    case MobilityModel::kStatic:
      break;
    case MobilityModel::kRandomWalk:
      out << " at " << m.random_walk.speed << " m/s, a new direction every "
          << m.random_walk.change_interval << " s";
      break;
    case MobilityModel::kRandomWaypoint:
      out << " at " << m.random_waypoint.speed_min << "-" << m.random_waypoint.speed_max
          << " m/s, pause " << m.random_waypoint.pause << " s";
      break;
    case MobilityModel::kGaussMarkov:
      out << " at " << m.gauss_markov.speed << " m/s, alpha " << m.gauss_markov.alpha << ", step "
          << m.gauss_markov.step << " s";
      break;
    case MobilityModel::kCrowd:
      out << " to within " << m.crowd.radius << " m of (" << m.crowd.target.x << ", "
          << m.crowd.target.y << ") at " << m.crowd.speed << " m/s from " << m.crowd.start
          << " s, for " << m.crowd.dwell << " s";
      break;
  }
  return out.str();
}

}  // namespace rlpos
