#include "common/mobility/trajectory_builder.h"

#include <cmath>

#include "common/config/config_error.h"
#include "common/config/object_reader.h"

namespace rlpos {
namespace {

// Whole nanoseconds: ns-3's Time holds exactly these, so the packet level plays the same knots.
double ToNanoseconds(double t) {
  return std::round(t * 1e9) / 1e9;
}

}  // namespace

TrajectoryBuilder::TrajectoryBuilder(const Scenario& scenario, const WalkableArea& area,
                                     std::size_t ue, double horizon)
    : area_(area),
      path_(JoinPath(JoinPath("/ues", ue), "mobility")),
      label_("UE \"" + scenario.ues[ue].name + "\" (" +
             MobilityModelName(scenario.ues[ue].mobility.model) + ")"),
      horizon_(horizon),
      position_(scenario.ues[ue].position) {
  waypoints_.push_back({0.0, position_});
}

void TrajectoryBuilder::Add(double time, const Vec3& position) {
  time_ = ToNanoseconds(time);
  position_ = position;
  waypoints_.push_back({time_, position_});
}

void TrajectoryBuilder::WalkTo(const Vec3& to, double speed) {
  const Vec3 end{to.x, to.y, position_.z};
  const double length = std::hypot(end.x - position_.x, end.y - position_.y);
  if (length == 0.0)
    return;
  Add(time_ + length / speed, end);
}

void TrajectoryBuilder::WalkRoute(const std::vector<Vec3>& route, double speed) {
  for (const Vec3& p : route)
    WalkTo(p, speed);
}

void TrajectoryBuilder::Wait(double seconds) {
  if (seconds > 0.0)
    Add(time_ + seconds, position_);
}

std::optional<Vec3> TrajectoryBuilder::DrawSpot(MobilityRandom& random, const Vec3& center,
                                                std::optional<double> radius) const {
  for (int draw = 0; draw < kMaxMobilityDraws; ++draw) {
    Vec3 p{0.0, 0.0, position_.z};
    if (radius) {
      // Uniform in the disc: the square root of a uniform radius fraction.
      const double r = *radius * std::sqrt(random.Uniform(0.0, 1.0));
      const double a = random.Angle();
      p.x = center.x + r * std::cos(a);
      p.y = center.y + r * std::sin(a);
    } else {
      p.x = random.Uniform(0.0, area_.width());
      p.y = random.Uniform(0.0, area_.depth());
    }
    if (area_.Contains(p.x, p.y))
      return p;
  }
  return std::nullopt;
}

std::optional<std::vector<Vec3>> TrajectoryBuilder::FindRoute(MobilityRandom& random,
                                                              const Vec3& to) const {
  const Vec3& from = position_;
  if (area_.LegIsClear(from, to))
    return std::vector<Vec3>{to};
  // Round one corner: a spot both ends see.
  for (int draw = 0; draw < kMaxMobilityDraws; ++draw) {
    const auto via = DrawSpot(random, from);
    if (via && area_.LegIsClear(from, *via) && area_.LegIsClear(*via, to))
      return std::vector<Vec3>{*via, to};
  }
  // Round two: a spot seen from here, one seen from the end, that see each other.
  for (int draw = 0; draw < kMaxMobilityDraws; ++draw) {
    const auto a = DrawSpot(random, from);
    const auto b = DrawSpot(random, from);
    if (a && b && area_.LegIsClear(from, *a) && area_.LegIsClear(*a, *b) &&
        area_.LegIsClear(*b, to))
      return std::vector<Vec3>{*a, *b, to};
  }
  return std::nullopt;
}

void TrajectoryBuilder::Fail(const std::string& why) const {
  throw ConfigError(path_, label_ + ": " + why);
}

UeTrajectory TrajectoryBuilder::Finish() && {
  return UeTrajectory(std::move(waypoints_));
}

}  // namespace rlpos
