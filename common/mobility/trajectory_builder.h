#pragma once
// What every mobility model does with its draws: walk legs and wait, on a clock that stops at
// the horizon, and fail with a one-line error naming the UE when the geometry leaves no way.
#include <optional>
#include <string>
#include <vector>

#include "common/mobility/mobility_random.h"
#include "common/mobility/ue_trajectory.h"
#include "common/mobility/walkable_area.h"

namespace rlpos {

// Draws of a point or a leg before a model gives up on a UE (then a ConfigError).
constexpr int kMaxMobilityDraws = 1000;

class TrajectoryBuilder {
 public:
  // `ue` indexes scenario.ues; the trajectory starts at its position at t = 0.
  TrajectoryBuilder(const Scenario& scenario, const WalkableArea& area, std::size_t ue,
                    double horizon);

  const WalkableArea& area() const { return area_; }
  const Vec3& position() const { return position_; }
  double time() const { return time_; }
  // The horizon is reached: later waypoints would never be seen.
  bool Done() const { return time_ >= horizon_; }

  // Straight to `to` (x, y; the UE keeps its height) at `speed` m/s; the leg must be clear.
  void WalkTo(const Vec3& to, double speed);
  void WalkRoute(const std::vector<Vec3>& route, double speed);
  void Wait(double seconds);

  // A spot of the walkable area drawn uniformly in the disc of `radius` around `center` (the
  // whole venue when radius is unset), or nullopt after kMaxMobilityDraws draws.
  std::optional<Vec3> DrawSpot(MobilityRandom& random, const Vec3& center,
                               std::optional<double> radius = std::nullopt) const;
  // Legs from the position now to `to` that avoid every building: straight if clear, else via
  // one or two spots drawn in the venue; nullopt when no draw found one.
  std::optional<std::vector<Vec3>> FindRoute(MobilityRandom& random, const Vec3& to) const;

  // Throws ConfigError at /ues/<i>/mobility: "UE "<name>" (<model>): <why>".
  [[noreturn]] void Fail(const std::string& why) const;

  UeTrajectory Finish() &&;

 private:
  void Add(double time, const Vec3& position);

  const WalkableArea& area_;
  std::string path_;
  std::string label_;
  double horizon_;
  double time_ = 0.0;
  Vec3 position_;
  std::vector<Waypoint> waypoints_;
};

}  // namespace rlpos
