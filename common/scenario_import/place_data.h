#pragma once
// What a map file holds for an import, before any projection: building outlines and parts as
// polygons in WGS84 longitude and latitude, street centre lines, the extent of the data, and
// what the reader had to skip. The OpenStreetMap and GeoJSON readers both fill it.
#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario_import/rlpos3_import.h"

namespace rlpos {

struct LonLat {
  double lon = 0, lat = 0;
};

// Open: the first point is not repeated at the end.
using GeoRing = std::vector<LonLat>;

struct GeoPolygon {
  GeoRing outer;
  std::vector<GeoRing> holes;
};

struct GeoBox {
  double min_lon = 0, min_lat = 0, max_lon = 0, max_lat = 0;
  bool Contains(const LonLat& p) const {
    return p.lon >= min_lon && p.lon <= max_lon && p.lat >= min_lat && p.lat <= max_lat;
  }
  bool Meets(const GeoBox& o) const {
    return min_lon <= o.max_lon && o.min_lon <= max_lon && min_lat <= o.max_lat &&
           o.min_lat <= max_lat;
  }
  // Grows the box to hold p.
  void Extend(const LonLat& p) {
    min_lon = std::min(min_lon, p.lon);
    min_lat = std::min(min_lat, p.lat);
    max_lon = std::max(max_lon, p.lon);
    max_lat = std::max(max_lat, p.lat);
  }
};

// A building outline (building=*) or part (building:part=*), as the file gives it.
struct PlaceFeature {
  // Names the element in messages: "way 123", "relation 45", "/features/3".
  std::string source;
  // For the scenario's building names: "way/123", "relation/45", "feature/3".
  std::string id;
  bool is_part = false;
  // The tags the import reads (PlaceTagKeys), as text; a GeoJSON number is written as JSON
  // writes it.
  std::map<std::string, std::string> tags;
  std::vector<GeoPolygon> polygons;
  int rings_repaired = 0;  // by the reader (an unclosed ring closed)
};

struct PlaceData {
  std::vector<PlaceFeature> features;
  std::vector<std::vector<LonLat>> streets;  // highway=* centre lines
  std::optional<GeoBox> extent;              // the data's area; unset for an empty file
  int missing_nodes = 0;                     // ways skipped: nodes missing (a cut extract)
  int incomplete_relations = 0;              // multipolygons skipped: member ways missing
  int rings_dropped = 0;                     // rings the reader could not build
  std::vector<ImportWarning> warnings;       // naming the element (way, relation, JSON path)
};

// What building:part and building make of a feature: a part when building:part is set (even
// with building=* beside it, as some parts are tagged), else an outline when building is set;
// "no" sets neither.
enum class BuildingRole { kNone, kOutline, kPart };
BuildingRole RoleOf(const char* building, const char* building_part);

// The tags of a feature the import reads: name, building, building:part, height,
// building:levels, min_height, building:min_level, roof:height.
const std::vector<std::string>& PlaceTagKeys();

}  // namespace rlpos
