#pragma once
// Buildings of a map may overlap once projected, and a scenario's buildings must not share
// volume. Neighbours that share a wall without sharing its nodes sit millimetres into each
// other (a node of one drawn onto the other's wall lies a rounding away from it); parts are
// drawn inside larger parts (a dome inside its church, from the ground up: 3-D renderers draw
// the union); some outlines are drawn over their neighbours. So:
// - walls that nearly coincide are snapped together first (a corner within kSnapDistance of
//   another building's corner moves onto it; one that close to another building's wall becomes
//   a corner of that wall too), which trims the slivers;
// - a building inside a larger one that rises above it starts on the larger one's top
//   (stacked: the union stays the same), one that adds nothing to its volume is dropped;
// - of two that still overlap (by the scenario's own rule, BuildingsOverlap), the smaller is
//   dropped.
// Buildings one above the other's height range do not overlap.
#include <vector>

#include "common/geometry/footprint.h"
#include "common/scenario_import/place_footprints.h"

namespace rlpos {

constexpr double kSnapDistance = 0.05;  // m: a few times OpenStreetMap's coordinate step

struct OverlapCounts {
  int trimmed = 0;  // overlapping pairs that snapping made neighbours
  int stacked = 0;  // buildings set on the top of a larger one they stood in
  int dropped = 0;  // buildings dropped for overlapping a larger one
};

// Snaps, stacks, then drops the smaller of each pair still overlapping; the rest keep their
// order. `level_height` counts a stacked building's floors.
void ResolveOverlaps(std::vector<PlaceBuilding>& buildings, double level_height,
                     OverlapCounts& counts, std::vector<ImportWarning>& warnings);

}  // namespace rlpos
