// The import's option texts and checks: each error names its option.
#include "common/scenario_import/place_options.h"

#include <gtest/gtest.h>

#include "common/config/config_error.h"

namespace rlpos {
namespace {

template <typename F>
std::string OptionErrorOf(F&& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

TEST(PlaceOptions, CenterSizeAndBox) {
  const LonLat c = ParsePlaceCenter("60.1695,24.9521");
  EXPECT_DOUBLE_EQ(c.lat, 60.1695);
  EXPECT_DOUBLE_EQ(c.lon, 24.9521);
  const VenueSize s = ParseVenueSize("400x300");
  EXPECT_DOUBLE_EQ(s.width, 400);
  EXPECT_DOUBLE_EQ(s.depth, 300);
  EXPECT_DOUBLE_EQ(ParseVenueSize("250").depth, 250);
  const GeoBox b = ParsePlaceBbox("24.946,60.167,24.953,60.171");
  EXPECT_DOUBLE_EQ(b.min_lon, 24.946);
  EXPECT_DOUBLE_EQ(b.max_lat, 60.171);
}

TEST(PlaceOptions, BadTextsNameTheirOption) {
  EXPECT_EQ(OptionErrorOf([] { ParsePlaceCenter("24.9521"); }).substr(0, 30),
            "--center: expected LAT,LON in ");
  EXPECT_EQ(OptionErrorOf([] { ParsePlaceCenter("95,24"); }).substr(0, 10), "--center: ");
  EXPECT_EQ(OptionErrorOf([] { ParseVenueSize("400x"); }),
            "--size: expected WxD in metres (e.g. 400x300), got \"400x\"");
  EXPECT_EQ(OptionErrorOf([] { ParseVenueSize("5000x300"); }),
            "--size: a venue side must be 10 to 2000 m, got 5000 m");
  EXPECT_EQ(OptionErrorOf([] { ParsePlaceBbox("24.953,60.167,24.946,60.171"); }).substr(0, 8),
            "--bbox: ");
  EXPECT_EQ(OptionErrorOf([] { ParsePlaceFormat("shp"); }),
            "--from: unknown format \"shp\" (known: osm, geojson, rlpos3)");
}

TEST(PlaceOptions, FormatFromTheExtension) {
  EXPECT_EQ(PlaceFormatOfFile("data/osm/helsinki-central.osm.pbf"), PlaceFormat::kOsm);
  EXPECT_EQ(PlaceFormatOfFile("a/b.OSM"), PlaceFormat::kOsm);
  EXPECT_EQ(PlaceFormatOfFile("x.osm.bz2"), PlaceFormat::kOsm);
  EXPECT_EQ(PlaceFormatOfFile("x.geojson"), PlaceFormat::kGeoJson);
  EXPECT_EQ(OptionErrorOf([] { PlaceFormatOfFile("x.shp"); }),
            "unknown extension: expected .osm, .osm.pbf, .pbf, .osm.gz or .osm.bz2 "
            "(OpenStreetMap), .geojson or .json (GeoJSON)");
  EXPECT_EQ(PlaceFileStem("data/osm/helsinki-central.osm.pbf"), "helsinki-central");
}

TEST(PlaceOptions, TheVenue) {
  PlaceImportOptions o;
  o.bbox = GeoBox{24.946, 60.167, 24.953, 60.171};
  const PlaceVenue v = ResolvePlaceVenue(o);
  EXPECT_DOUBLE_EQ(v.center.lon, 24.9495);
  EXPECT_DOUBLE_EQ(v.size.width, 389);  // 0.007 degrees of longitude at 60.169 N
  EXPECT_DOUBLE_EQ(v.size.depth, 446);
  o.center = LonLat{24.9, 60.1};
  EXPECT_EQ(OptionErrorOf([&] { ResolvePlaceVenue(o); }),
            "--bbox: give either --bbox or --center with --size, not both");
  o.bbox.reset();
  EXPECT_EQ(OptionErrorOf([&] { ResolvePlaceVenue(o); }),
            "--size: --center needs --size WxD (metres)");
  o.size = VenueSize{100, 100};
  o.uavs = 7;
  EXPECT_EQ(OptionErrorOf([&] { ResolvePlaceVenue(o); }), "--uavs: expected 1 to 6 UAVs, got 7");
  o.uavs = 2;
  EXPECT_EQ(ResolvedUeCount(o), 14);  // the generator's urban default for two UAVs
  o.ue_groups = 15;
  EXPECT_EQ(OptionErrorOf([&] { ResolvePlaceVenue(o); }),
            "--ue-groups: expected 0 (no groups) to the UE count (14), got 15");
}

}  // namespace
}  // namespace rlpos
