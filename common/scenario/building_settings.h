#pragma once
// A building of the scenario (each of "buildings"), declared once (building_settings.cc) for the
// parser, ToJson and the docs.
#include <string>

#include "common/config/setting.h"
#include "common/scenario/geometry.h"

namespace rlpos {

// An ns-3 Building: an axis-aligned box on the ground.
struct BuildingSpec {
  std::string name;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  double height = 10.0;
  int floors = 1;
  int rooms_x = 1;
  int rooms_y = 1;
  std::string type = "residential";
  std::string walls = "concrete_with_windows";
  Box Footprint3d() const { return {xmin, xmax, ymin, ymax, 0.0, height}; }
};

const SettingsTable<BuildingSpec>& BuildingSettings();

}  // namespace rlpos
