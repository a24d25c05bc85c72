#pragma once
// A scenario's buildings as geometry: their ground shapes, their solids, and the Obstacles that
// decide line of sight (common/geometry/obstacles.h) for every part of RLpos.
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/building_settings.h"

namespace rlpos {

// Its footprint, or its box's rectangle (counter-clockwise from the low corner).
Footprint GroundShape(const BuildingSpec& building);
// Its solid: a box building's box [0, height], or its footprint between min_height and height.
Solid BuildingSolid(const BuildingSpec& building);
// The buildings' solids, in the scenario's order (solid i is building i).
Obstacles BuildingObstacles(const std::vector<BuildingSpec>& buildings);

// The building holds `p` (boundary included): the same answer as its Solid's.
bool BuildingHolds(const BuildingSpec& building, const Vec3& p);
// Its ground shape holds (x, y) (boundary included), whatever its heights.
bool GroundShapeHolds(const BuildingSpec& building, double x, double y);

}  // namespace rlpos
