#pragma once
// OpenStreetMap files (.osm XML, .osm.pbf, compressed XML) read with libosmium: building
// outlines and parts from closed ways and multipolygon relations (libosmium's area
// assembler, which also finds the inner rings), street centre lines from highway=* ways.
#include <string>

#include "common/scenario_import/place_data.h"

namespace rlpos {

// The file's buildings, parts and streets that come near `area` (elsewhere they are skipped
// unread), and the extent of the data: the header's bounding box (an extract's, <bounds> in
// XML), else that of all its nodes. Ways with nodes missing from the file (a cut
// extract) are skipped and counted, with a warning when they come near `area`; so are
// multipolygons whose member ways are missing. Unclosed building ways are closed (repaired);
// rings the assembler cannot build (self-intersecting) are dropped and counted. A file that
// cannot be read throws ConfigError::AboutFile.
PlaceData ReadOsmFile(const std::string& file, const GeoBox& area);

}  // namespace rlpos
