#pragma once
// The map files of these tests (data/: small OpenStreetMap XML and GeoJSON files written for
// them, around 60.0 N, 25.0 E) and the shipped extract (data/osm/), imported with options, and
// what an import fails with.
#include <algorithm>
#include <cmath>
#include <string>

#include "common/config/config_error.h"
#include "common/scenario/scenario.h"
#include "common/scenario_import/place_import.h"

namespace rlpos {

inline std::string FixturePath(const std::string& name) {
  return std::string(RLPOS_SOURCE_DIR) + "/tests/common/scenario_import/data/" + name;
}

inline std::string ShippedExtract() {
  return std::string(RLPOS_SOURCE_DIR) + "/data/osm/helsinki-central.osm.pbf";
}

// The fixtures' venue: 100 m x 100 m around 60.0, 25.0, four UEs, seed 1.
inline PlaceImportOptions FixtureOptions(const std::string& name) {
  PlaceImportOptions o;
  o.file = FixturePath(name);
  o.center = LonLat{25.0, 60.0};
  o.size = VenueSize{100, 100};
  o.ues = 4;
  o.seed = 1;
  return o;
}

// The import's error as a user reads it ("<path>: <problem>"), or "".
inline std::string PlaceErrorOf(const PlaceImportOptions& options) {
  try {
    ImportPlace(options);
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

// The warnings about `source` ("way 12"), joined by " | ".
inline std::string WarningsAbout(const PlaceImportResult& result, const std::string& source) {
  std::string out;
  for (const auto& w : result.warnings) {
    if (w.path == source)
      out += (out.empty() ? "" : " | ") + w.message;
  }
  return out;
}

// `p` stands off every footprint of `s` and at least 1 m from its walls (checked here on its own,
// not with the import's Outdoors).
inline bool ClearOfBuildings(const Scenario& s, const Vec3& p) {
  auto near_wall = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % ring.size()];
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double t =
          std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      if (std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy) < 1.0)
        return true;
    }
    return false;
  };
  for (const auto& b : s.buildings) {
    if (Contains(b.footprint, {p.x, p.y}) || near_wall(b.footprint.outer))
      return false;
    if (std::any_of(b.footprint.holes.begin(), b.footprint.holes.end(), near_wall))
      return false;
  }
  return true;
}

// Every warning, "<path>: <message>", joined by " | ".
inline std::string AllWarnings(const PlaceImportResult& result) {
  std::string out;
  for (const auto& w : result.warnings)
    out += (out.empty() ? "" : " | ") + w.path + ": " + w.message;
  return out;
}

}  // namespace rlpos
