#pragma once
// A building of the scenario (each of "buildings"), declared once (building_settings.cc) for the
// parser, ToJson and the docs.
#include <string>

#include "common/config/setting.h"
#include "common/geometry/footprint.h"
#include "common/scenario/geometry.h"

namespace rlpos {

// A building: either an ns-3 Building, an axis-aligned box [xmin, xmax] x [ymin, ymax] x
// [0, height] ("x", "y"), or an exact ground shape, a polygon with holes extruded between
// min_height and height ("footprint", "holes"). For a footprint building xmin..ymax hold the
// footprint's bounding box, so that code that knows only boxes still sees its extent.
struct BuildingSpec {
  std::string name;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  // Empty outer ring: a box building.
  Footprint footprint;
  double height = 10.0;
  // Where a footprint building starts (a part above a passage, a bridge); a box's is 0.
  double min_height = 0.0;
  int floors = 1;
  int rooms_x = 1;
  int rooms_y = 1;
  std::string type = "residential";
  std::string walls = "concrete_with_windows";
  bool HasFootprint() const { return !footprint.outer.empty(); }
  // Makes it a footprint building: sets `footprint` and the bounding box with it.
  void SetFootprint(Footprint shape);
  // The box itself, or a footprint building's bounding box between its heights.
  Box Footprint3d() const { return {xmin, xmax, ymin, ymax, min_height, height}; }
};

const SettingsTable<BuildingSpec>& BuildingSettings();

}  // namespace rlpos
