#pragma once
// The paper's "positions 1-5, each 10 m from the optimal position in different directions":
// position k is `distance` metres from the RL position towards +x, -x, +y, -y, +z (k = 1..5),
// kept where the UAV may actually fly. Pure geometry, no ns-3.
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"

namespace rlpos {

constexpr int kOffsetCount = 5;
constexpr double kOffsetDistance = 10.0;  // m
// How far an offset stops short of a building face on its way (rlpos-sim refuses a UAV inside a
// building, boundary included, so an offset must end strictly outside).
constexpr double kObstacleMargin = 0.5;  // m

struct OffsetGeometry {
  Box bounds;                    // where the UAV may be: the scenario's uav.zone within the venue
  std::vector<Solid> obstacles;  // building volumes: boxes, or footprints between two heights
};

OffsetGeometry OffsetGeometryOf(const Scenario& scenario);

// Unit vector of position k (1..5): +x, -x, +y, -y, +z. Throws std::out_of_range otherwise.
Vec3 OffsetDirection(int k);

// Position k around `center`: center + distance * direction, clamped to the bounds; if the
// straight path there meets a building, it stops kObstacleMargin before the first face it meets
// (so it is the nearest flyable point in that direction). A clamped position is closer than
// `distance`; it is never farther.
Vec3 OffsetPosition(const Vec3& center, int k, const OffsetGeometry& geometry,
                    double distance = kOffsetDistance);

// Positions 1..5 in order.
std::vector<Vec3> OffsetPositions(const Vec3& center, const OffsetGeometry& geometry,
                                  double distance = kOffsetDistance);

}  // namespace rlpos
