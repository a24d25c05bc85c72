#pragma once
// GeoJSON files (RFC 7946): a FeatureCollection whose Polygon and MultiPolygon features are
// buildings, in WGS84 longitude and latitude. Their properties are read as OpenStreetMap tags
// (PlaceTagKeys: height, building:levels, min_height, building:min_level, roof:height, name; a
// number or a text). When any feature has a "building" or "building:part" property, only those
// features are buildings (an export of a whole map); otherwise every polygon is one (a
// building layer). LineString and MultiLineString features with a "highway" property are
// streets; other features are skipped.
#include <string>

#include "common/scenario_import/place_data.h"

namespace rlpos {

// The buildings and streets of the file that come near `area`, and the extent of the data: the
// collection's "bbox" when it has one, else that of all its coordinates. A structural error throws
// ConfigError naming its JSON path
// ("/features/3/geometry/coordinates/0/2: expected [longitude, latitude]"); an unclosed ring is
// closed and counted as repaired.
PlaceData ReadGeoJsonFile(const std::string& file, const GeoBox& area);

}  // namespace rlpos
