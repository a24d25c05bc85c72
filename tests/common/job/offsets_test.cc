#include "common/job/offsets.h"

#include <gtest/gtest.h>

#include "common/job/position_rule.h"
#include "common/scenario/scenario_parser.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;

OffsetGeometry OpenSky() {
  return {{0, 100, 0, 100, 5, 60}, {}};
}

OffsetGeometry ScenarioBGeometry() {
  return OffsetGeometryOf(
      ParseScenario(ReadJsonFile(testing::SourcePath("campaigns/scenarios/b.json"))));
}

void ExpectAt(const Vec3& p, double x, double y, double z) {
  EXPECT_DOUBLE_EQ(p.x, x);
  EXPECT_DOUBLE_EQ(p.y, y);
  EXPECT_DOUBLE_EQ(p.z, z);
}

TEST(Offsets, TenMetresInFiveDirections) {
  const auto p = OffsetPositions({50, 50, 20}, OpenSky());
  ASSERT_EQ(p.size(), 5u);
  ExpectAt(p[0], 60, 50, 20);  // +x
  ExpectAt(p[1], 40, 50, 20);  // -x
  ExpectAt(p[2], 50, 60, 20);  // +y
  ExpectAt(p[3], 50, 40, 20);  // -y
  ExpectAt(p[4], 50, 50, 30);  // +z
}

TEST(Offsets, ClampedToTheZone) {
  const auto p = OffsetPositions({95, 3, 55}, OpenSky());
  ExpectAt(p[0], 100, 3, 55);
  ExpectAt(p[1], 85, 3, 55);
  ExpectAt(p[3], 95, 0, 55);
  ExpectAt(p[4], 95, 3, 60);
}

TEST(Offsets, GeometryIsTheZoneWithinTheVenue) {
  Scenario s = ParseScenario(ReadJsonFile(testing::SourcePath("campaigns/scenarios/b.json")));
  s.uavs[0].zone = {20, 80, 10, 90, 5, 40};
  const OffsetGeometry g = OffsetGeometryOf(s);
  EXPECT_DOUBLE_EQ(g.bounds.xmin, 20);
  EXPECT_DOUBLE_EQ(g.bounds.xmax, 80);
  EXPECT_DOUBLE_EQ(g.bounds.zmax, 40);
  ExpectAt(OffsetPosition({75, 60, 35}, 1, g), 80, 60, 35);
  ExpectAt(OffsetPosition({75, 60, 35}, 5, g), 75, 60, 40);
}

TEST(Offsets, StopShortOfBuildings) {
  const OffsetGeometry b = ScenarioBGeometry();
  // Tower: x, y in [45, 55], 20 m. Its west face is 5 m away: stop 0.5 m before it.
  ExpectAt(OffsetPosition({40, 50, 10}, 1, b), 44.5, 50, 10);
  // From the corridor (50, 35): +y would end on the tower's south face (y = 45, touching counts).
  ExpectAt(OffsetPosition({50, 35, 10}, 3, b), 50, 44.5, 10);
  // -y: the south block (y in [18, 26], 25 m) is 9 m away.
  ExpectAt(OffsetPosition({50, 35, 10}, 4, b), 50, 26.5, 10);
  // Free directions from the corridor are the full 10 m.
  ExpectAt(OffsetPosition({50, 35, 10}, 1, b), 60, 35, 10);
  ExpectAt(OffsetPosition({50, 35, 10}, 5, b), 50, 35, 20);
}

TEST(Offsets, PassOverLowBuildings) {
  const OffsetGeometry b = ScenarioBGeometry();
  // 5 m above the 20 m tower, the baseline flies over it freely.
  ExpectAt(OffsetPosition({50, 50, 25}, 1, b), 60, 50, 25);
  ExpectAt(OffsetPosition({50, 50, 25}, 4, b), 50, 40, 25);
}

// An L-shaped building, arms x 40-60 (y 40-45) and y 40-60 (x 40-45), 20 m tall, over open sky.
OffsetGeometry Ell() {
  OffsetGeometry g = OpenSky();
  g.obstacles.push_back(
      Solid::Prism({{{40, 40}, {60, 40}, {60, 45}, {45, 45}, {45, 60}, {40, 60}}, {}}, 0, 20));
  return g;
}

TEST(Offsets, AFootprintStopsThemAtItsWallsNotItsBoundingBox) {
  // From the L's notch (inside its bounding box, outside the building).
  const auto p = OffsetPositions({52, 52, 10}, Ell());
  ExpectAt(p[0], 62, 52, 10);    // +x: open ground
  ExpectAt(p[1], 45.5, 52, 10);  // -x: stops 0.5 m short of the west arm (x 45)
  ExpectAt(p[2], 52, 62, 10);    // +y: open ground
  ExpectAt(p[3], 52, 45.5, 10);  // -y: short of the south arm (y 45)
  // Over the west arm, below its roof: +z leaves it; from under a part that starts above ground,
  // +z stops below it.
  ExpectAt(OffsetPositions({42, 52, 10}, Ell())[4], 42, 52, 20);
  OffsetGeometry arch = OpenSky();
  arch.obstacles.push_back(Solid::Prism({{{30, 30}, {60, 30}, {60, 35}, {30, 35}}, {}}, 12, 20));
  ExpectAt(OffsetPositions({40, 32, 5}, arch)[4], 40, 32, 11.5);
}

TEST(PositionRule, AFootprintObstacleRoundTrips) {
  PositionRule rule;
  rule.offset = 2;
  rule.geometry = Ell();
  const json text = ToJson(rule);
  EXPECT_EQ(text["obstacles"][0]["z"], json({0, 20}));
  const PositionRule back = PositionRuleFromJson(json::parse(text.dump()));
  EXPECT_EQ(ToJson(back), text);
  ExpectAt(ApplyPositionRule(back, {{52, 52, 10}}).at(0), 45.5, 52, 10);
  json bad = text;
  bad["obstacles"][0]["footprint"] = json::array({{0, 0}, {1, 1}, {0, 1}, {1, 0}});  // a bow tie
  EXPECT_THROW(PositionRuleFromJson(bad), std::invalid_argument);
}

TEST(Offsets, UnknownPositionIndex) {
  EXPECT_THROW(OffsetDirection(0), std::out_of_range);
  EXPECT_THROW(OffsetDirection(6), std::out_of_range);
}

TEST(PositionRule, JsonRoundTripAndApply) {
  PositionRule rule;
  rule.offset = 3;
  rule.geometry = ScenarioBGeometry();
  const PositionRule back = PositionRuleFromJson(nlohmann::json::parse(ToJson(rule).dump()));
  EXPECT_EQ(back.offset, 3);
  EXPECT_EQ(back.geometry.obstacles.size(), 5u);
  ExpectAt(ApplyPositionRule(back, {{50, 35, 10}}).at(0), 50, 44.5, 10);
  ExpectAt(ApplyPositionRule(PositionRule{}, {{1, 2, 3}}).at(0), 1, 2, 3);  // rl: as produced
  // rl of several UAVs: as produced; offsets are defined around one UAV.
  EXPECT_EQ(ApplyPositionRule(PositionRule{}, {{1, 2, 3}, {4, 5, 6}}).size(), 2u);
  EXPECT_THROW(ApplyPositionRule(back, {{1, 2, 3}, {4, 5, 6}}), std::invalid_argument);
  EXPECT_THROW(PositionRuleFromJson({{"offset", 9}}), std::invalid_argument);
  EXPECT_THROW(PositionRuleFromJson({{"offset", 1}}), std::invalid_argument);
  EXPECT_THROW(PositionRuleFromJson("x"), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
