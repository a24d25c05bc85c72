// Buildings as exact footprints: "footprint" (and "holes", "min_height") instead of "x" and "y";
// read, written back, checked with errors that name their path, and turned into the Obstacles
// that decide line of sight. Box buildings keep their JSON byte for byte (the golden files too).
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "common/scenario/building_checks.h"
#include "common/scenario/building_obstacles.h"
#include "common/scenario/scenario_checks.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

// [10, 40] x [60, 90] with the courtyard [20, 30] x [70, 80], 15 m.
json Court() {
  return json::parse(R"({"name": "court", "footprint": [[10, 60], [40, 60], [40, 90], [10, 90]],
                         "holes": [[[20, 70], [20, 80], [30, 80], [30, 70]]], "height": 15})");
}

// A part from 4 m to 8 m over a passage: [60, 70] x [80, 95].
json Bridge() {
  return json::parse(R"({"name": "bridge", "footprint": [[60, 80], [70, 80], [70, 95], [60, 95]],
                         "min_height": 4, "height": 8})");
}

// Scenario B (UEs at (85, 25), (70, 60), (30, 50), (5, 15); the UAV at (50, 50, 25)) with
// these buildings instead of its own.
json WithBuildings(const std::vector<json>& buildings) {
  json doc = ShippedScenarioDocument("b");
  doc["buildings"] = json::array();
  for (const auto& b : buildings)
    doc["buildings"].push_back(b);
  return doc;
}

TEST(FootprintBuilding, Parses) {
  const Scenario s = ParseScenario(WithBuildings({Court(), Bridge()}));
  ASSERT_EQ(s.buildings.size(), 2u);
  const BuildingSpec& court = s.buildings[0];
  EXPECT_TRUE(court.HasFootprint());
  EXPECT_EQ(court.footprint.outer.size(), 4u);
  ASSERT_EQ(court.footprint.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(court.footprint), 900.0 - 100.0);
  // Its bounding box, for code that knows only boxes.
  EXPECT_EQ(court.xmin, 10);
  EXPECT_EQ(court.xmax, 40);
  EXPECT_EQ(court.ymin, 60);
  EXPECT_EQ(court.ymax, 90);
  EXPECT_EQ(court.min_height, 0);
  EXPECT_EQ(s.buildings[1].min_height, 4);
  // The exact shape decides what is inside.
  EXPECT_EQ(BuildingContaining(s, {15, 75, 1.5}), 0);
  EXPECT_EQ(BuildingContaining(s, {25, 75, 1.5}), -1);  // the courtyard
  EXPECT_EQ(BuildingContaining(s, {65, 85, 1.5}), -1);  // under the bridge
  EXPECT_EQ(BuildingContaining(s, {65, 85, 6}), 1);
  EXPECT_EQ(FootprintContaining(s, 25, 75), -1);
  EXPECT_EQ(FootprintContaining(s, 65, 85), 1);
}

TEST(FootprintBuilding, RoundTripsThroughToJson) {
  const Scenario s = ParseScenario(WithBuildings({Court(), Bridge()}));
  const json doc = ToJson(s);
  const json& court = doc["buildings"][0];
  EXPECT_FALSE(court.contains("x"));
  EXPECT_FALSE(court.contains("y"));
  EXPECT_FALSE(court.contains("min_height"));  // 0: not written
  EXPECT_EQ(court["footprint"], Court()["footprint"]);
  EXPECT_EQ(court["holes"], Court()["holes"]);
  EXPECT_EQ(doc["buildings"][1]["min_height"], 4.0);
  EXPECT_FALSE(doc["buildings"][1].contains("holes"));
  EXPECT_EQ(ToJson(ParseScenario(doc)), doc);
}

TEST(FootprintBuilding, ARepeatedClosingPointIsDropped) {
  json court = Court();
  court["footprint"].push_back({10, 60});
  const Scenario s = ParseScenario(WithBuildings({court}));
  EXPECT_EQ(s.buildings[0].footprint.outer.size(), 4u);
  EXPECT_EQ(ToJson(s)["buildings"][0]["footprint"], Court()["footprint"]);
}

TEST(FootprintBuilding, BoxesKeepTheirKeys) {
  const json doc = ToJson(ParseScenario(ShippedScenarioDocument("b")));
  const std::set<std::string> want{"name", "x", "y", "height", "floors", "rooms", "type", "walls"};
  for (const auto& b : doc["buildings"]) {
    std::set<std::string> keys;
    for (const auto& [key, value] : b.items())
      keys.insert(key);
    EXPECT_EQ(keys, want);
  }
}

// Buildings that share walls, overlap by less than the tolerance, or stand one above the other
// are fine; so is a UE in a courtyard, and a static one under a bridge.
TEST(FootprintBuilding, NeighboursAndCourtyardsAreFine) {
  json east = Court();  // [40, 60] x [60, 90]: shares the wall x = 40
  east["name"] = "east";
  east.erase("holes");
  east["footprint"] = json::parse("[[40, 60], [60, 60], [60, 90], [40, 90]]");
  // A box 1 m wide reaching half a millimetre (half the tolerance) into the court's west wall.
  const json sliver = json::parse(R"({"x": [9, 10.0005], "y": [60, 90], "height": 5})");
  json above = Bridge();  // over the east building's roof
  above["name"] = "above";
  above["min_height"] = 15;
  above["height"] = 20;
  above["footprint"] = east["footprint"];
  json doc = WithBuildings({Court(), east, sliver, above});
  doc["ues"][2]["position"] = {25, 75, 1.5};
  EXPECT_EQ(ErrorOf(doc, {}), "");
  doc = WithBuildings({Bridge()});
  doc["ues"][2]["position"] = {65, 85, 1.5};
  EXPECT_EQ(ErrorOf(doc, {}), "");
}

struct BadBuilding {
  const char* name;
  std::vector<json> buildings;
  std::vector<std::string> overrides;
  std::string expected;  // the error's start: its path and words
};

class FootprintBuildingRefused : public ::testing::TestWithParam<BadBuilding> {};

TEST_P(FootprintBuildingRefused, NamesThePath) {
  const std::string error = ErrorOf(WithBuildings(GetParam().buildings), GetParam().overrides);
  EXPECT_EQ(error.rfind(GetParam().expected, 0), 0u)
      << "got: \"" << error << "\", expected to start with: \"" << GetParam().expected << "\"";
}

json With(json building, const std::string& key, const json& value) {
  building[key] = value;
  return building;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FootprintBuildingRefused,
    ::testing::Values(
        BadBuilding{"BothShapes",
                    {With(Court(), "x", {10, 40})},
                    {},
                    "/buildings/0/x: a building is a box (x and y) or a footprint, not both"},
        BadBuilding{"NoShape",
                    {json{{"height", 10}}},
                    {},
                    "/buildings/0/x: is required ([xmin, xmax]; or a footprint instead of x, y)"},
        BadBuilding{"HolesOnABox",
                    {json::parse(R"({"x": [0, 10], "y": [0, 10], "height": 5,
                                     "holes": [[[2, 2], [3, 2], [3, 3]]]})")},
                    {},
                    "/buildings/0/holes: holes need a footprint"},
        BadBuilding{"MinHeightOnABox",
                    {json::parse(R"({"x": [0, 10], "y": [0, 10], "height": 5, "min_height": 1})")},
                    {},
                    "/buildings/0/min_height: needs a footprint"},
        BadBuilding{"MinHeightNotBelowHeight",
                    {With(Bridge(), "min_height", 8)},
                    {},
                    "/buildings/0/min_height: must be below height (8), got 8"},
        BadBuilding{"NegativeMinHeight",
                    {With(Bridge(), "min_height", -1)},
                    {},
                    "/buildings/0/min_height: must not be negative, got -1"},
        BadBuilding{"TwoPoints",
                    {With(Court(), "footprint", json::parse("[[0, 0], [1, 1]]"))},
                    {},
                    "/buildings/0/footprint: expected at least 3 points [x, y], got 2"},
        BadBuilding{"TwoPointsClosed",
                    {With(Court(), "footprint", json::parse("[[0, 0], [1, 1], [0, 0]]"))},
                    {},
                    "/buildings/0/footprint: expected at least 3 points [x, y], got 2 besides the "
                    "repeated first one"},
        BadBuilding{"PointNotAPair",
                    {With(Court(), "footprint", json::parse("[[0, 0, 0], [1, 0], [1, 1]]"))},
                    {},
                    "/buildings/0/footprint/0: expected [x, y], got an array of 3"},
        BadBuilding{"HolesNotAList",
                    {With(Court(), "holes", json::parse("[[20, 70], [20, 80], [30, 80]]"))},
                    {},
                    "/buildings/0/holes/0/0: expected [x, y], got a number"},
        BadBuilding{
            "BowTie",
            {With(Court(), "footprint", json::parse("[[10, 60], [40, 90], [40, 60], [10, 90]]"))},
            {},
            "/buildings/0/footprint: not a simple polygon: edges 0 and 2 cross"},
        BadBuilding{
            "HoleBowTie",
            {With(Court(), "holes", json::parse("[[[20, 70], [30, 80], [30, 70], [20, 80]]]"))},
            {},
            "/buildings/0/holes/0: edges 0 and 2 cross"},
        BadBuilding{
            "HoleOutside",
            {With(Court(), "holes", json::parse("[[[50, 70], [50, 80], [55, 80], [55, 70]]]"))},
            {},
            "/buildings/0/holes/0: reaches outside the outer ring"},
        BadBuilding{"HolesOverlap",
                    {With(Court(), "holes",
                          json::parse("[[[20, 70], [20, 80], [30, 80], [30, 70]],"
                                      " [[25, 75], [25, 85], [35, 85], [35, 75]]]"))},
                    {},
                    "/buildings/0/holes/1: overlaps hole 0"},
        BadBuilding{
            "HoleFillsIt",
            {With(Court(), "holes", json::parse("[[[10, 60], [40, 60], [40, 90], [10, 90]]]"))},
            {},
            "/buildings/0/holes: the holes leave no area"},
        BadBuilding{
            "OutsideTheVenue",
            {With(Court(), "footprint", json::parse("[[-5, 60], [40, 60], [40, 90], [-5, 90]]"))},
            {},
            "/buildings/0/footprint: building \"court\" [-5, 40] x [60, 90] x [0, 15] is "
            "outside the venue"},
        BadBuilding{"TooTall",
                    {With(Court(), "height", 70)},
                    {},
                    "/buildings/0: building \"court\" [10, 40] x [60, 90] x [0, 70] is outside"},
        BadBuilding{"OverABox",
                    {Court(), json::parse(R"({"name": "shed", "x": [35, 45], "y": [85, 95],
                                             "height": 3})")},
                    {},
                    "/buildings/1: building \"shed\" overlaps building 0 (\"court\")"},
        BadBuilding{"OverABoxPastAnother",
                    {Court(), json::parse(R"({"x": [12, 13], "y": [95, 99], "height": 3})"),
                     json::parse(R"({"name": "shed", "x": [35, 45], "y": [85, 95],
                                     "height": 3})")},
                    {},
                    "/buildings/2: building \"shed\" overlaps building 0 (\"court\")"},
        BadBuilding{"InTheCourtyardAndOverTheWall",
                    {Court(), json::parse(R"({"name": "kiosk", "footprint": [[18, 72], [22, 72],
                                             [22, 74], [18, 74]], "height": 3})")},
                    {},
                    "/buildings/1: building \"kiosk\" overlaps building 0 (\"court\")"},
        BadBuilding{"IntoTheBridge",
                    {Bridge(), json::parse(R"({"name": "tall", "footprint": [[65, 90], [75, 90],
                                             [75, 99], [65, 99]], "height": 5})")},
                    {},
                    "/buildings/1: building \"tall\" overlaps building 0 (\"bridge\")"},
        BadBuilding{"UeInside",
                    {Court()},
                    {"ues.2.position=[15, 75, 1.5]"},
                    "/ues/2/position: UE at (15, 75, 1.5) is inside building 0 (\"court\")"},
        BadBuilding{"UavInside",
                    {Court()},
                    {"uav.position=[15, 75, 10]"},
                    "/uav/position: UAV at (15, 75, 10) is inside building 0 (\"court\")"},
        BadBuilding{"MobileUeUnderTheBridge",
                    {Bridge()},
                    {"ues.2.position=[65, 85, 1.5]",
                     R"(ues.2.mobility={"model": "random_walk", "speed": 1})"},
                    "/ues/2/position: UE \"ue2\" moves (random_walk) but starts on building 0"},
        BadBuilding{"CrowdTargetInside",
                    {Court()},
                    {R"(ues.1.mobility={"model": "crowd", "target": [12, 62]})"},
                    "/ues/1/mobility/target: crowd target (12, 62) is inside building 0"}),
    [](const ::testing::TestParamInfo<BadBuilding>& param) {
      return std::string(param.param.name);
    });

TEST(BuildingObstacles, OneSolidPerBuilding) {
  json doc = WithBuildings({Court(), Bridge(), json::parse(R"({"x": [80, 90], "y": [40, 50],
                                                               "height": 10})")});
  doc["ues"][2]["position"] = {25, 75, 1.5};
  const Scenario s = ParseScenario(doc);
  const Obstacles o = BuildingObstacles(s.buildings);
  ASSERT_EQ(o.size(), 3u);
  EXPECT_FALSE(o.solid(0).IsBox());
  EXPECT_EQ(o.solid(1).box.zmin, 4);
  EXPECT_TRUE(o.solid(2).IsBox());
  EXPECT_EQ(o.solid(2).box.zmax, 10);
  // From the courtyard: up to the UAV, out through the wall, along the passage under the bridge.
  EXPECT_TRUE(o.Los({25, 75, 1.5}, {25, 75, 30}));
  EXPECT_FALSE(o.Los({25, 75, 1.5}, {5, 75, 1.5}));
  EXPECT_TRUE(o.Los({65, 75, 1.5}, {65, 99, 1.5}));
  EXPECT_FALSE(o.Los({65, 75, 6}, {65, 99, 6}));
  EXPECT_FALSE(o.Los({75, 45, 5}, {95, 45, 5}));
  for (const Vec3& p : {Vec3{15, 75, 1.5}, Vec3{25, 75, 1.5}, Vec3{65, 85, 6}, Vec3{85, 45, 1}})
    EXPECT_EQ(o.SolidAt(p), BuildingContaining(s, p));
}

}  // namespace
}  // namespace rlpos
