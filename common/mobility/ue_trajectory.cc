#include "common/mobility/ue_trajectory.h"

#include <algorithm>
#include <stdexcept>

namespace rlpos {

UeTrajectory::UeTrajectory(std::vector<Waypoint> waypoints) : waypoints_(std::move(waypoints)) {
  if (waypoints_.empty())
    throw std::invalid_argument("a UE trajectory needs at least one waypoint");
  for (std::size_t i = 1; i < waypoints_.size(); ++i) {
    if (waypoints_[i].time < waypoints_[i - 1].time)
      throw std::invalid_argument("UE trajectory waypoints go back in time");
  }
}

UeTrajectory UeTrajectory::Still(const Vec3& position) {
  return UeTrajectory({{0.0, position}});
}

Vec3 UeTrajectory::PositionAt(double t) const {
  if (t <= waypoints_.front().time)
    return waypoints_.front().position;
  if (t >= waypoints_.back().time)
    return waypoints_.back().position;
  // The first waypoint after t; the one before it is at or before t.
  const auto next = std::upper_bound(waypoints_.begin(), waypoints_.end(), t,
                                     [](double time, const Waypoint& w) { return time < w.time; });
  const Waypoint& b = *next;
  const Waypoint& a = *(next - 1);
  const double f = (t - a.time) / (b.time - a.time);
  return {a.position.x + (b.position.x - a.position.x) * f,
          a.position.y + (b.position.y - a.position.y) * f,
          a.position.z + (b.position.z - a.position.z) * f};
}

bool UeTrajectory::Moves() const {
  const Vec3& first = waypoints_.front().position;
  return std::any_of(waypoints_.begin(), waypoints_.end(), [&](const Waypoint& w) {
    return w.position.x != first.x || w.position.y != first.y || w.position.z != first.z;
  });
}

}  // namespace rlpos
