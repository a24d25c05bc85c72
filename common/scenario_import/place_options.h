#pragma once
// What `rlpos-sim import --from osm|geojson` is asked for, and the option texts it parses: the
// file, the venue (a centre and a size, or a longitude/latitude box), the UEs, UAVs and seed,
// and the height rules. Errors are ConfigError naming the option ("--center").
#include <cstdint>
#include <optional>
#include <string>

#include "common/scenario_import/osm_heights.h"
#include "common/scenario_import/place_data.h"

namespace rlpos {

enum class PlaceFormat { kOsm, kGeoJson };

struct VenueSize {
  double width = 0, depth = 0;  // m, east-west and north-south
};

// The largest venue side (m): the local projection's error is measured up to 2 km.
constexpr double kMaxPlaceVenueSide = 2000.0;
constexpr double kMinPlaceVenueSide = 10.0;

struct PlaceImportOptions {
  std::string file;                   // .osm .osm.pbf .pbf .osm.gz .osm.bz2 | .geojson .json
  std::optional<PlaceFormat> format;  // --from; unset: the file's extension decides
  std::optional<LonLat> center;       // --center LAT,LON (with --size)
  std::optional<VenueSize> size;      // --size WxD (m)
  std::optional<GeoBox> bbox;         // --bbox MINLON,MINLAT,MAXLON,MAXLAT (instead of both)
  std::optional<int> ues;             // --ues; unset: the generator's urban default for `uavs`
  int ue_groups = 0;                  // --ue-groups: 0 draws each UE on its own
  int uavs = 1;                       // --uavs
  std::uint64_t seed = 0;             // --seed
  HeightRules heights;                // --level-height, --default-height (m)
  std::string name;                   // --name; "": "osm-<file stem>" or "geojson-<file stem>"
};

// "osm" or "geojson" (--from).
PlaceFormat ParsePlaceFormat(const std::string& text);
std::string PlaceFormatName(PlaceFormat format);
// The format the file's name says; an unknown extension is ConfigError::AboutFile.
PlaceFormat PlaceFormatOfFile(const std::string& file);
// "LAT,LON" in degrees (--center 60.1695,24.9521).
LonLat ParsePlaceCenter(const std::string& text);
// "WxD" in metres (--size 400x300), or one number for a square.
VenueSize ParseVenueSize(const std::string& text);
// "MINLON,MINLAT,MAXLON,MAXLAT" in degrees (--bbox), as osmium and OpenStreetMap write it.
GeoBox ParsePlaceBbox(const std::string& text);

// The venue the options select: its centre and size.
struct PlaceVenue {
  LonLat center;
  VenueSize size;
};

// Checks the options (one venue, counts in range) and resolves the venue: a box's centre is
// its midpoint and its size the box measured through that centre, to the metre.
PlaceVenue ResolvePlaceVenue(const PlaceImportOptions& options);
// The UE count the options give or imply.
int ResolvedUeCount(const PlaceImportOptions& options);
// The file's name without its folders and known extensions ("helsinki" for
// "data/osm/helsinki.osm.pbf").
std::string PlaceFileStem(const std::string& file);

}  // namespace rlpos
