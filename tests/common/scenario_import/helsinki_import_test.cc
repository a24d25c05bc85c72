// The shipped extract of central Helsinki (data/osm/helsinki-central.osm.pbf) at the three
// venues data/osm/README.md recommends: what each holds, the same bytes from the same options,
// every UE outdoors, and what ParseScenario makes of it.
#include <gtest/gtest.h>

#include "common/scenario/scenario_parser.h"
#include "tests/common/scenario_import/place_fixtures.h"

namespace rlpos {
namespace {

PlaceImportOptions Venue(double lat, double lon, double side) {
  PlaceImportOptions o;
  o.file = ShippedExtract();
  o.center = LonLat{lon, lat};
  o.size = VenueSize{side, side};
  o.ues = 20;
  o.ue_groups = 2;
  o.seed = 7;
  return o;
}

// data/osm/README.md's venues.
PlaceImportOptions SenateSquare() {
  return Venue(60.1697, 24.9505, 300);
}
PlaceImportOptions HarbourFront() {
  return Venue(60.1670, 24.9505, 300);
}
PlaceImportOptions DenseBlocks() {
  return Venue(60.1665, 24.9449, 400);
}

struct Counts {
  int buildings, from_height, from_levels, from_default, parts, clipped, ways_skipped;
};

void ExpectCounts(const PlaceImportResult& r, const Counts& c) {
  const PlaceSummary& s = r.summary;
  EXPECT_EQ(s.buildings, c.buildings);
  EXPECT_EQ(s.from_height, c.from_height);
  EXPECT_EQ(s.from_levels, c.from_levels);
  EXPECT_EQ(s.from_default, c.from_default);
  EXPECT_EQ(s.parts, c.parts);
  EXPECT_EQ(s.clipped, c.clipped);
  EXPECT_EQ(s.ways_skipped, c.ways_skipped);  // streets the raw extract's edge cut
  EXPECT_EQ(s.rings_dropped, 0);
  EXPECT_EQ(s.bad_heights, 0);
  EXPECT_TRUE(s.ues_on_streets);
}

void ExpectOutdoors(const PlaceImportResult& r) {
  // ParseScenario checks that no UE or UAV is inside a building; on top of that, every UE
  // keeps its metre from the walls.
  const Scenario s = ParseScenario(r.document);
  EXPECT_EQ(s.ues.size(), 20u);
  for (const auto& ue : s.ues)
    EXPECT_TRUE(ClearOfBuildings(s, ue.position)) << ue.name;
}

// The counts are this extract's: a change to them is a change to the import (or the data).
TEST(HelsinkiImport, SenateSquare) {
  const PlaceImportResult r = ImportPlace(SenateSquare());
  ExpectCounts(r, {44, 11, 13, 20, 21, 18, 17});
  // The cathedral's dome stands on its body, the lantern on the dome.
  EXPECT_EQ(r.summary.overlaps_stacked, 3);
  EXPECT_EQ(WarningsAbout(r, "way 234870674"),
            "stands inside \"way/419479425\" (way 419479425): it starts on its top, 20 m");
  ExpectOutdoors(r);
}

TEST(HelsinkiImport, HarbourFront) {
  const PlaceImportResult r = ImportPlace(HarbourFront());
  ExpectCounts(r, {43, 6, 9, 28, 10, 12, 15});
  ExpectOutdoors(r);
}

TEST(HelsinkiImport, DenseBlocks) {
  const PlaceImportResult r = ImportPlace(DenseBlocks());
  ExpectCounts(r, {85, 1, 22, 62, 10, 29, 7});
  EXPECT_EQ(PlaceSummaryLine(r.summary),
            "400 x 400 m: 85 buildings (height 1, levels 22, default 62; 10 parts, 8 above the "
            "ground); clipped 29, outlines replaced 7; rings repaired 0, dropped 0; overlaps "
            "trimmed 0, stacked 0, dropped 1; bad heights 0; skipped ways 7, relations 0; 20 UEs "
            "along the streets in 2 groups; 1 UAV");
  ExpectOutdoors(r);
}

TEST(HelsinkiImport, SameOptionsSameBytes) {
  const PlaceImportResult a = ImportPlace(DenseBlocks());
  const PlaceImportResult b = ImportPlace(DenseBlocks());
  EXPECT_EQ(a.json_text, b.json_text);
  PlaceImportOptions other = DenseBlocks();
  other.seed = 8;  // another seed moves the UEs, not the buildings
  const PlaceImportResult c = ImportPlace(other);
  EXPECT_NE(a.json_text, c.json_text);
  EXPECT_EQ(a.document.at("buildings"), c.document.at("buildings"));
}

}  // namespace
}  // namespace rlpos
