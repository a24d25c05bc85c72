#pragma once
// A building's ground shape as a map needs it, in metres, no drawing: where inside it a label may
// be centred, and whether a label's rectangle fits in it (internal to worker/map).
#include <vector>

#include "common/geometry/footprint.h"
#include "common/scenario/building_settings.h"

namespace rlpos::map {

// Points inside the building's ground shape to centre its label on, best first. A box: its
// centre only, as before footprints (its maps keep their bytes). A footprint: its bounding box's
// centre and its centroid when inside (an L's may not be), then the middles of the inside
// stretches along a few lines across it, each centred across too, the longest stretch first.
std::vector<Point2> LabelPoints(const BuildingSpec& building);

// The rectangle lies in the shape; touching its boundary is fine.
bool RectangleInside(const Footprint& shape, const Bounds2& rectangle);

}  // namespace rlpos::map
