#pragma once
// What the page draws a scenario map from (JSON): each scenario of the campaign as its spec
// holds it (venue, zones, buildings, UEs, UAVs' initial positions), and where each positioner
// put the UAVs in its first succeeded eval run; with track runs, the frames of each track
// positioner's first run (track_frames.h).
#include <nlohmann/json.hpp>
#include <string>

#include "common/store/results_reader.h"

namespace rlpos::web {

// {"scenarios": [{"name", "file", "venue", "buildings", "ues", "uavs", "placements":
// [{"positioner", "rng_run", "uavs": [{"name", "x", "y", "z"}]}], "tracks"}]}, "tracks" only for a
// scenario with a succeeded track run (TrackFramesJson). A building is {"name", "xmin", "xmax",
// "ymin", "ymax", "height", "floors"}; a footprint building adds "footprint" ([[x, y], ...], the
// outer ring, open), "holes" ([ring, ...]) and "min_height", its xmin..ymax being the footprint's
// bounding box. A scenario whose document no longer parses gets {"file", "error"} instead.
// nullopt for an unknown campaign.
std::optional<nlohmann::json> ScenarioMapsJson(ResultsReader& store,
                                               const std::string& campaign_id);

}  // namespace rlpos::web
