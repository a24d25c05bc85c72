#pragma once
// What a map shows, as data: the scenario, one or more named placements of its UAVs, each UE's
// link to its serving UAV (for a map of one placement), walked and flown paths. Computing the links
// needs ns-3 (map_links.h); drawing them does not (map_render.h).
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos::map {

// One UE's link at the placement drawn: to which UAV, and whether the buildings block it.
struct MapLink {
  int serving_uav = 0;  // index in the scenario's order
  bool los = false;
};

// A placement as a positioner gave it: one position per UAV, in the scenario's order.
struct MapPlacement {
  std::string label;  // "baseline", "oracle", "rl", "position", ...
  Placement positions;
  int n_los = -1;  // UEs in LoS of their serving UAV at this placement; -1: unknown
};

// The positions one UAV flew through, in order (an rl evaluation episode).
struct FlightPath {
  int uav = 0;
  std::vector<Vec3> points;
};

struct MapScene {
  Scenario scenario;
  // One: its UAVs are drawn with their links and the UEs coloured by them. Several: each is a
  // marker of its own (a comparison of positioners), without links.
  std::vector<MapPlacement> placements;
  std::vector<MapLink> links;  // per UE, for placements.front(); empty: not drawn
  std::vector<FlightPath> flight;
  std::string flight_label = "rl flight";
  // The paths moving UEs walk (their trajectories' waypoints, per UE; empty: a static UE).
  std::vector<std::vector<Vec3>> ue_paths;
  std::string ue_paths_label = "UE paths";
  bool side_views = false;  // add the x-z and y-z elevation views
};

}  // namespace rlpos::map
