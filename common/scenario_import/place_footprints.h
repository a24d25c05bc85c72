#pragma once
// Map features -> footprints in the venue's frame: each polygon projected (centimetres), its
// rings cleaned and checked, building outlines that hold parts replaced by the parts, heights
// from the tags, and everything clipped to the venue.
#include <string>
#include <vector>

#include "common/geometry/footprint.h"
#include "common/scenario/building_settings.h"
#include "common/scenario_import/local_projection.h"
#include "common/scenario_import/osm_heights.h"
#include "common/scenario_import/place_data.h"

namespace rlpos {

// The venue's rectangle on the map: [0, width] x [0, depth] m, its centre at the projection's
// origin.
struct VenueFrame {
  double width = 0, depth = 0;
};

struct PlaceBuilding {
  std::string name;    // unique: the map's name and element ("Stockmann (way/123)"), or the element
  std::string source;  // for messages: "way 123", "/features/3"
  Footprint footprint;
  ResolvedHeight height;
  bool is_part = false;
};

struct FootprintCounts {
  int clipped = 0;            // buildings cut by the venue's edge
  int outlines_replaced = 0;  // outlines dropped for the building:part polygons inside them
  int rings_repaired = 0;     // unclosed rings closed, spikes removed
  int rings_dropped = 0;      // rings that are not simple polygons (self-intersecting...)
  int bad_heights = 0;        // height tags that were not numbers (fell back)
};

// The building as the scenario holds it: its name, footprint, heights and floors (ns-3's
// defaults for the rest).
BuildingSpec PlaceBuildingSpec(const PlaceBuilding& building);

// Centimetres: the grid the scenario's coordinates are written on.
double RoundToCentimetre(double metres);

// A point of the map in the venue's frame, rounded to the centimetre.
Point2 ToVenue(const LonLat& p, const LocalProjection& projection, const VenueFrame& venue);
// A ring of the map in the venue's frame, rounded to the centimetre, without repeated points.
Ring ProjectRing(const GeoRing& ring, const LocalProjection& projection, const VenueFrame& venue);

// The buildings of `data` inside the venue, in the order of the file.
std::vector<PlaceBuilding> BuildFootprints(const PlaceData& data, const LocalProjection& projection,
                                           const VenueFrame& venue, const HeightRules& rules,
                                           FootprintCounts& counts,
                                           std::vector<ImportWarning>& warnings);

}  // namespace rlpos
