// A GeoJSON FeatureCollection (data/place.geojson) imported as a scenario: polygons with holes,
// multipolygons, properties read as tags, an unclosed ring with a spike, a street, a point.
#include <gtest/gtest.h>

#include "tests/common/scenario_import/place_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;

TEST(GeoJsonImport, PolygonsAndTheirProperties) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("place.geojson"));
  ASSERT_EQ(r.summary.buildings, 4);  // a polygon, a multipolygon of two, a repaired polygon
  const json& buildings = r.document.at("buildings");
  EXPECT_EQ(buildings[0].at("name"), "Courtyard block (feature/0)");
  EXPECT_EQ(buildings[0].at("height"), 15);
  EXPECT_EQ(buildings[0].at("holes").size(), 1u);
  EXPECT_EQ(buildings[1].at("name"), "feature/1");
  EXPECT_EQ(buildings[2].at("name"), "feature/1 #2");
  EXPECT_EQ(buildings[2].at("height"), 9);      // 3 levels
  EXPECT_EQ(buildings[3].at("height"), 12.19);  // "40 ft"
  EXPECT_EQ(buildings[3].at("min_height"), 1);
  EXPECT_EQ(buildings[3].at("footprint").size(), 5u);  // the spike is gone
  EXPECT_EQ(r.summary.rings_repaired, 2);              // closed, and its spike removed
  EXPECT_EQ(WarningsAbout(r, "/features/2"),
            "1 ring(s) not closed: closed from the last position to the first | outline: 1 "
            "spike(s) (an edge drawn out and back) removed");
  EXPECT_TRUE(r.summary.ues_on_streets);
  EXPECT_EQ(r.document.at("name"), "geojson-place");
}

TEST(GeoJsonImport, ErrorsNameTheJsonPath) {
  EXPECT_EQ(PlaceErrorOf(FixtureOptions("bad_position.geojson")),
            "/features/1/geometry/coordinates/0/1: expected [longitude, latitude] in degrees");
  EXPECT_EQ(PlaceErrorOf(FixtureOptions("rlpos3_full.json")),
            "/type: expected a GeoJSON FeatureCollection");
}

}  // namespace
}  // namespace rlpos
