#pragma once
// A real place as a scenario (`rlpos-sim import --from osm|geojson`): the buildings of an
// OpenStreetMap extract or a GeoJSON file inside a venue (a centre and a size, or a
// longitude/latitude box) as exact footprints, clipped to the venue, with heights from their
// tags; UEs drawn outdoors along the streets; UAVs, radio, traffic and the loss model as
// `rlpos-sim generate` makes them. Same options and file, same bytes, on any machine.
//
// The venue's frame: the origin at its south-west corner, x east, y north, from a local
// tangent plane at its centre (local_projection.h); coordinates to the centimetre.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/scenario_import/place_options.h"
#include "common/scenario_import/rlpos3_import.h"

namespace rlpos {

// What the import did, for one line on stderr (PlaceSummaryLine) and for tests. Buildings are
// counted as written (a building the edge cuts in two counts twice).
struct PlaceSummary {
  double width = 0, depth = 0;  // the venue (m)
  int buildings = 0;
  int parts = 0;         // of them, building:part polygons
  int above_ground = 0;  // of them, starting above the ground (min_height > 0)
  int from_height = 0;   // height from the height tag
  int from_levels = 0;   // from building:levels x the level height
  int from_default = 0;  // the default height
  int clipped = 0;       // map polygons cut by the venue's edge
  int outlines_replaced = 0;
  int rings_repaired = 0;
  int rings_dropped = 0;
  int overlaps_trimmed = 0;   // overlapping pairs snapped into neighbours
  int overlaps_stacked = 0;   // parts set on the top of a larger part they stood in
  int overlaps_dropped = 0;   // buildings dropped for overlapping a larger one
  int bad_heights = 0;        // height tags that were not numbers
  int ways_skipped = 0;       // ways with nodes missing from the file (near the venue)
  int relations_skipped = 0;  // multipolygons with members missing
  int street_segments = 0;    // street pieces in the venue
  int ues = 0;
  int ue_groups = 0;
  bool ues_on_streets = false;
  int uavs = 0;
};

struct PlaceImportResult {
  // The scenario, as ParseScenario reads it, and its text as it should be written (as the
  // generator writes its scenarios: GeneratedJsonText).
  nlohmann::json document;
  std::string json_text;
  PlaceSummary summary;
  // In a fixed order; each names the element ("way 123", "relation 45", "/features/3") or the
  // option ("--center"). Callers prefix the file's name, as for ConfigError.
  std::vector<ImportWarning> warnings;
};

// Imports the place; the document has passed ParseScenario (structure, ranges, geometry: no
// two buildings share a volume, no UE or UAV is in one). Errors are ConfigError, one line each
// with describe(), to which callers prefix the file's name: a bad option names the option
// ("--center: the venue's centre ... is outside the data (...)"); a file that cannot be read,
// has an unknown extension or holds no data is ConfigError::AboutFile; a malformed GeoJSON
// element names its JSON path; a building the scenario's checks reject names its map element
// ("way 123: ... (as the scenario's /buildings/7)").
PlaceImportResult ImportPlace(const PlaceImportOptions& options);

// One line: "400 x 300 m: 142 buildings (height 20, levels 80, default 42; 12 parts, 5 above
// the ground); clipped 12, outlines replaced 3; rings repaired 2, dropped 1; overlaps trimmed 4,
// stacked 2, dropped 1; bad heights 2; skipped ways 3, relations 0; 10 UEs along the streets in 2
// groups; 1 UAV". Without buildings it says "no buildings".
std::string PlaceSummaryLine(const PlaceSummary& summary);

// The command that reproduces `options`, with the file's name alone (no folders).
std::string PlaceCommandLine(const PlaceImportOptions& options);

}  // namespace rlpos
