// OpenStreetMap XML fixtures (data/*.osm) imported as scenarios: each case of the format, and
// each kind of bad input, as one fixture.
#include <gtest/gtest.h>

#include "common/scenario/scenario_parser.h"
#include "tests/common/scenario_import/place_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;

const json& BuildingNamed(const json& doc, const std::string& name) {
  for (const auto& b : doc.at("buildings")) {
    if (b.at("name") == name)
      return b;
  }
  static const json none;
  ADD_FAILURE() << "no building " << name;
  return none;
}

// Every UE of the document stands outdoors, a metre clear of every footprint.
void ExpectUesOutdoors(const json& doc) {
  const Scenario s = ParseScenario(doc);
  for (const auto& ue : s.ues)
    EXPECT_TRUE(ClearOfBuildings(s, ue.position)) << ue.name;
}

TEST(OsmImport, CourtyardStaysOpenGround) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("courtyard.osm"));
  ASSERT_EQ(r.summary.buildings, 1);
  const json& b = BuildingNamed(r.document, "Courtyard block (relation/1)");
  ASSERT_EQ(b.at("holes").size(), 1u);
  EXPECT_EQ(b.at("footprint").size(), 4u);
  EXPECT_EQ(b.at("height"), 15);
  EXPECT_EQ(b.at("floors"), 5);
  // The outer ring 20..60, the courtyard 30..50, to the centimetre.
  const auto& corner = b.at("footprint")[0];
  EXPECT_NEAR(corner[0].get<double>(), 20, 0.011);
  EXPECT_NEAR(corner[1].get<double>(), 20, 0.011);
  EXPECT_EQ(r.summary.from_height, 1);
  EXPECT_TRUE(r.summary.ues_on_streets);
  EXPECT_EQ(r.summary.street_segments, 1);
  // Its outer way is tagged building=yes too: the relation, with its courtyard, is the building.
  EXPECT_EQ(AllWarnings(r),
            "way 10: also the outline of relation 1: that relation's polygon is the building");
  ExpectUesOutdoors(r.document);
  for (const auto& ue : r.document.at("ues"))  // on the street at y = 10
    EXPECT_NEAR(ue.at("position")[1].get<double>(), 10, 0.5);
  // What ParseScenario makes of it: one footprint building with its hole.
  const Scenario s = ParseScenario(r.document);
  ASSERT_EQ(s.buildings.size(), 1u);
  EXPECT_EQ(s.buildings[0].footprint.holes.size(), 1u);
}

TEST(OsmImport, PartsReplaceTheirOutline) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("parts.osm"));
  EXPECT_EQ(r.summary.buildings, 4);
  EXPECT_EQ(r.summary.parts, 3);
  EXPECT_EQ(r.summary.outlines_replaced, 1);
  EXPECT_EQ(r.summary.above_ground, 2);
  EXPECT_EQ(r.summary.overlaps_dropped, 0);  // the set-back storey stands on the west part
  EXPECT_EQ(WarningsAbout(r, "way 30"), "outline replaced by the building:part polygons inside it");
  const json& east = BuildingNamed(r.document, "way/32");
  EXPECT_EQ(east.at("min_height"), 6);
  EXPECT_EQ(east.at("height"), 24);
  EXPECT_EQ(east.at("floors"), 6);
  const json& storey = BuildingNamed(r.document, "way/33");
  EXPECT_EQ(storey.at("min_height"), 10);
  EXPECT_EQ(storey.at("height"), 20);
  EXPECT_EQ(BuildingNamed(r.document, "way/34").at("height"), 6);  // 2 levels of 3 m
  EXPECT_EQ(r.summary.from_height, 2);
  EXPECT_EQ(r.summary.from_levels, 2);
  ExpectUesOutdoors(r.document);
}

TEST(OsmImport, PartsInsidePartsStackOrGo) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("nested_parts.osm"));
  EXPECT_EQ(r.summary.buildings, 3);  // body, dome, lantern; the stair tower adds nothing
  EXPECT_EQ(r.summary.outlines_replaced, 1);
  EXPECT_EQ(r.summary.overlaps_stacked, 2);
  EXPECT_EQ(r.summary.overlaps_dropped, 1);
  const json& dome = BuildingNamed(r.document, "way/102");
  EXPECT_EQ(dome.at("min_height"), 20);  // on the body's top
  EXPECT_EQ(dome.at("height"), 38);
  const json& lantern = BuildingNamed(r.document, "way/103");
  EXPECT_EQ(lantern.at("min_height"), 38);  // on the dome's
  EXPECT_EQ(lantern.at("height"), 41);
  EXPECT_EQ(WarningsAbout(r, "way 102"),
            "stands inside \"way/101\" (way 101): it starts on its top, 20 m");
  EXPECT_EQ(WarningsAbout(r, "way 104"),
            "lies within the volume of the larger building \"way/101\" (way 101): dropped");
  ExpectUesOutdoors(r.document);
}

TEST(OsmImport, TheEdgeCutsABuilding) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("edge.osm"));
  EXPECT_EQ(r.summary.buildings, 2);  // way 41 lies outside
  EXPECT_EQ(r.summary.clipped, 1);
  const json& cut = BuildingNamed(r.document, "way/40");
  double xmax = 0;
  for (const auto& p : cut.at("footprint"))
    xmax = std::max(xmax, p[0].get<double>());
  EXPECT_EQ(xmax, 100);
  EXPECT_FALSE(r.summary.ues_on_streets);  // no street: anywhere outdoors
  ExpectUesOutdoors(r.document);
}

TEST(OsmImport, HeightsInMetresAndFeet) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("feet.osm"));
  EXPECT_EQ(r.summary.from_height, 6);
  EXPECT_EQ(BuildingNamed(r.document, "way/50").at("height"), 12.19);  // 40 ft
  EXPECT_EQ(BuildingNamed(r.document, "way/51").at("height"), 12.19);  // 40'
  EXPECT_EQ(BuildingNamed(r.document, "way/52").at("height"), 12.5);
  EXPECT_EQ(BuildingNamed(r.document, "way/53").at("height"), 12);
  EXPECT_EQ(BuildingNamed(r.document, "way/54").at("height"), 12.34);  // 40'6"
  EXPECT_EQ(BuildingNamed(r.document, "way/55").at("height"), 7);
  EXPECT_EQ(AllWarnings(r), "");
}

TEST(OsmImport, BadHeightsFallBackAndAreCounted) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("bad_heights.osm"));
  EXPECT_EQ(r.summary.bad_heights, 4);
  EXPECT_EQ(r.summary.from_levels, 1);
  EXPECT_EQ(r.summary.from_default, 2);
  EXPECT_EQ(r.summary.from_height, 1);
  EXPECT_EQ(BuildingNamed(r.document, "way/56").at("height"), 12);
  EXPECT_EQ(BuildingNamed(r.document, "way/57").at("height"), 10);
  EXPECT_EQ(WarningsAbout(r, "way 57"),
            "height \"12;15\" is not a height in metres or feet: the default is used");
  EXPECT_EQ(WarningsAbout(r, "way 58"),
            "building:levels \"many\" is not a number of levels from 1 to 200: the default "
            "height 10 m is used");
  EXPECT_EQ(WarningsAbout(r, "way 59"),
            "min_height \"low\" is not a height in metres or feet: the building stands on the "
            "ground");
}

TEST(OsmImport, CutExtractSkipsWhatIsMissing) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("cut_extract.osm"));
  EXPECT_EQ(r.summary.buildings, 1);
  EXPECT_EQ(r.summary.ways_skipped, 1);
  EXPECT_EQ(r.summary.relations_skipped, 1);
  EXPECT_EQ(WarningsAbout(r, "way 60"), "lacks 1 of its 5 nodes (a cut extract): skipped");
  EXPECT_EQ(WarningsAbout(r, "relation 2"),
            "1 of its member ways are missing (a cut extract): skipped");
  BuildingNamed(r.document, "way/63");
}

TEST(OsmImport, BrokenRingsAreRepairedOrDropped) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("broken_rings.osm"));
  EXPECT_EQ(r.summary.buildings, 2);
  EXPECT_EQ(r.summary.rings_dropped, 1);
  EXPECT_EQ(r.summary.rings_repaired, 1);
  // The bow tie's edges cross at (20, 20) of the venue.
  EXPECT_EQ(WarningsAbout(r, "way 70").substr(0, 49),
            "no valid outline (its edges cross at 59.9997307,2");
  EXPECT_EQ(WarningsAbout(r, "way 71"), "not closed: closed from its last node to its first");
  EXPECT_EQ(BuildingNamed(r.document, "way/71").at("footprint").size(), 4u);
}

TEST(OsmImport, OverlapsAreTrimmedOrDropped) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("overlaps.osm"));
  EXPECT_EQ(r.summary.buildings, 2);
  EXPECT_EQ(r.summary.overlaps_dropped, 1);
  EXPECT_EQ(r.summary.overlaps_trimmed, 1);
  EXPECT_EQ(WarningsAbout(r, "way 81"),
            "overlaps the larger building \"way/80\" (way 80): dropped");
  // The neighbour's wall is now a stretch of the large one's: they share its corners.
  const json& large = BuildingNamed(r.document, "way/80");
  const json& small = BuildingNamed(r.document, "way/82");
  int shared = 0;
  for (const auto& p : small.at("footprint")) {
    for (const auto& q : large.at("footprint"))
      shared += p == q ? 1 : 0;
  }
  EXPECT_EQ(shared, 2);
}

TEST(OsmImport, NoBuildingsIsAScenarioToo) {
  const PlaceImportResult r = ImportPlace(FixtureOptions("no_buildings.osm"));
  EXPECT_EQ(r.summary.buildings, 0);
  EXPECT_TRUE(r.document.at("buildings").empty());
  EXPECT_EQ(PlaceSummaryLine(r.summary),
            "100 x 100 m: no buildings; clipped 0, outlines replaced 0; rings repaired 0, "
            "dropped 0; overlaps trimmed 0, stacked 0, dropped 0; bad heights 0; skipped ways 0, "
            "relations "
            "0; 4 UEs along the streets; 1 UAV");
  // The baseline of free space: the venue's centre, 10 m up.
  EXPECT_EQ(r.document.at("uav").at("position"), json::array({50, 50, 10}));
}

TEST(OsmImport, BadFilesAndVenues) {
  PlaceImportOptions o = FixtureOptions("absent.osm");
  EXPECT_EQ(PlaceErrorOf(o), "cannot open: No such file or directory");
  o = FixtureOptions("place.shp");
  EXPECT_EQ(PlaceErrorOf(o).substr(0, 18), "unknown extension:");
  o = FixtureOptions("courtyard.osm");
  o.format = PlaceFormat::kGeoJson;
  EXPECT_EQ(PlaceErrorOf(o),
            "--from: \"geojson\" does not read an OpenStreetMap file (by its extension)");
  o = FixtureOptions("courtyard.osm");
  o.center = LonLat{25.0, 61.0};
  EXPECT_EQ(PlaceErrorOf(o).substr(0, 55),
            "--center: the venue's centre 61,25 is outside the data ");
  o = FixtureOptions("empty.osm");
  EXPECT_EQ(PlaceErrorOf(o), "no data: the file holds no points (an empty extract)");
  o = FixtureOptions("truncated.osm");
  EXPECT_EQ(PlaceErrorOf(o).substr(0, 35), "not a readable OpenStreetMap file: ");
}

}  // namespace
}  // namespace rlpos
