#include "worker/positioning/track/uav_flight.h"

#include <algorithm>
#include <cmath>

#include "common/scenario/scenario_checks.h"

namespace rlpos {
namespace {

// Points on a leg checked against the buildings: at most this far apart (m).
constexpr double kLegSampling = 0.5;

Vec3 Clip(const Box& zone, const Vec3& p) {
  return {std::clamp(p.x, zone.xmin, zone.xmax), std::clamp(p.y, zone.ymin, zone.ymax),
          std::clamp(p.z, zone.zmin, zone.zmax)};
}

// The furthest point from `from` toward `to` within the two limits (m this interval).
Vec3 Limited(const Vec3& from, const Vec3& to, double horizontal, double vertical) {
  const double h = std::hypot(to.x - from.x, to.y - from.y);
  const double v = std::abs(to.z - from.z);
  double share = 1.0;
  if (h > horizontal)
    share = std::min(share, horizontal / h);
  if (v > vertical)
    share = std::min(share, vertical / v);
  if (share >= 1.0)
    return to;
  return {from.x + (to.x - from.x) * share, from.y + (to.y - from.y) * share,
          from.z + (to.z - from.z) * share};
}

bool LegIsClear(const Scenario& s, std::size_t uav, const Placement& now, const Vec3& from,
                const Vec3& to) {
  if (OverlapsAnother(now, uav, to))
    return false;
  const double length = std::hypot(to.x - from.x, to.y - from.y, to.z - from.z);
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / kLegSampling)));
  for (int i = 1; i <= pieces; ++i) {
    const double f = static_cast<double>(i) / pieces;
    const Vec3 p{from.x + (to.x - from.x) * f, from.y + (to.y - from.y) * f,
                 from.z + (to.z - from.z) * f};
    if (BuildingContaining(s, p) >= 0)
      return false;
  }
  return true;
}

}  // namespace

Vec3 FlyToward(const Scenario& s, std::size_t uav, const Placement& now, const Vec3& target,
               double seconds) {
  const UavSpec& spec = s.uavs[uav];
  const Vec3& from = now[uav];
  const double horizontal = spec.max_speed * seconds;
  const double vertical = spec.max_climb * seconds;
  const Vec3 goal = Clip(spec.zone, target);
  const Vec3 legs[] = {
      Limited(from, goal, horizontal, vertical),                              // straight
      Limited(from, {goal.x, goal.y, from.z}, horizontal, vertical),          // level
      Limited(from, {from.x, from.y, spec.zone.zmax}, horizontal, vertical),  // climb
  };
  for (const Vec3& leg : legs) {
    const Vec3 end = Clip(spec.zone, leg);
    if (LegIsClear(s, uav, now, from, end))
      return end;
  }
  return from;
}

double FlightSeconds(const UavSpec& uav, const Vec3& from, const Vec3& to) {
  const double horizontal = std::hypot(to.x - from.x, to.y - from.y);
  const double vertical = std::abs(to.z - from.z);
  return std::max(horizontal / uav.max_speed, vertical / uav.max_climb);
}

}  // namespace rlpos
