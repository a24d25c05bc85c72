// ues[].mobility in the scenario JSON: each model's parameters and defaults, the round trip
// through the writer, and every bad setting as a one-line error naming its JSON path.
#include <gtest/gtest.h>

#include "common/scenario/scenario_parser.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

// A 100 x 100 m venue with one building [40, 60] x [40, 60], two UEs on the ground, a UAV.
json Doc() {
  return json::parse(R"({
    "buildings": [{"name": "hall", "x": [40, 60], "y": [40, 60], "height": 20}],
    "uav": {"position": [80, 20, 10]},
    "ues": [{"position": [10, 10, 1.5], "demand": {"mbps": 5}},
            {"position": [90, 90, 1.5], "demand": {"mbps": 5}}]})");
}

Scenario ParseWith(const std::vector<std::string>& overrides) {
  json doc = Doc();
  ApplyOverrides(doc, overrides);
  return ParseScenario(doc);
}

TEST(MobilityParser, StaticIsTheDefault) {
  EXPECT_EQ(ParseWith({}).ues[0].mobility.model, MobilityModel::kStatic);
}

TEST(MobilityParser, EachModelReadsItsParameters) {
  const Scenario s = ParseWith(
      {R"(ues.0.mobility={"model": "random_waypoint", "speed": [0.8, 2], "pause": 0})",
       R"(ues.1.mobility={"model": "gauss_markov", "speed": 1.5, "alpha": 0.9, "step": 0.5})"});
  const auto& w = s.ues[0].mobility;
  EXPECT_EQ(w.model, MobilityModel::kRandomWaypoint);
  EXPECT_DOUBLE_EQ(w.random_waypoint.speed_min, 0.8);
  EXPECT_DOUBLE_EQ(w.random_waypoint.speed_max, 2.0);
  EXPECT_DOUBLE_EQ(w.random_waypoint.pause, 0.0);
  const auto& g = s.ues[1].mobility;
  EXPECT_EQ(g.model, MobilityModel::kGaussMarkov);
  EXPECT_DOUBLE_EQ(g.gauss_markov.speed, 1.5);
  EXPECT_DOUBLE_EQ(g.gauss_markov.alpha, 0.9);
  EXPECT_DOUBLE_EQ(g.gauss_markov.step, 0.5);
  const auto& c =
      ParseWith({R"(ues.0.mobility={"model": "crowd", "target": [20, 80], "dwell": 5})"})
          .ues[0]
          .mobility;
  EXPECT_EQ(c.model, MobilityModel::kCrowd);
  EXPECT_DOUBLE_EQ(c.crowd.target.x, 20.0);
  EXPECT_DOUBLE_EQ(c.crowd.target.y, 80.0);
  EXPECT_DOUBLE_EQ(c.crowd.dwell, 5.0);
  EXPECT_DOUBLE_EQ(c.crowd.radius, 10.0);  // the default
  EXPECT_DOUBLE_EQ(c.crowd.speed, 1.2);
}

TEST(MobilityParser, WriterRoundTripsEveryModel) {
  for (const char* mobility :
       {R"({"model": "static"})", R"({"model": "random_walk", "speed": 2, "change_interval": 3})",
        R"({"model": "random_waypoint", "speed": [0.5, 1], "pause": 4})",
        R"({"model": "gauss_markov", "speed": 1, "alpha": 0.5, "step": 2})",
        R"({"model": "crowd", "target": [20, 80], "radius": 5, "speed": 2, "start": 3,
            "dwell": 7})"}) {
    const Scenario s = ParseWith({std::string("ues.0.mobility=") + mobility});
    const json written = ToJson(s);
    EXPECT_EQ(written["ues"][0]["mobility"], json::parse(mobility)) << mobility;
    EXPECT_EQ(ToJson(ParseScenario(written)), written) << mobility;
  }
}

// Policies trained before the other models wrote random_walk's keys on static UEs.
TEST(MobilityParser, StaticAcceptsTheOldRandomWalkKeys) {
  EXPECT_EQ(
      ErrorOf(Doc(), {R"(ues.0.mobility={"model": "static", "speed": 1, "change_interval": 2})"}),
      "");
}

struct BadMobility {
  const char* mobility;
  const char* error;
};

class BadMobilitySettings : public ::testing::TestWithParam<BadMobility> {};

TEST_P(BadMobilitySettings, AreOneLineErrorsWithTheJsonPath) {
  const std::string error = ErrorOf(Doc(), {std::string("ues.1.mobility=") + GetParam().mobility});
  // Starts with: the enum and key errors go on with the allowed values or a "did you mean".
  EXPECT_EQ(error.substr(0, std::string(GetParam().error).size()), GetParam().error) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    MobilityParser, BadMobilitySettings,
    ::testing::Values(
        BadMobility{R"({"model": "teleport"})",
                    "/ues/1/mobility/model: unknown value \"teleport\""},
        BadMobility{R"({"model": "random_walk", "speed": -1})",
                    "/ues/1/mobility/speed: must be positive, got -1"},
        BadMobility{R"({"model": "random_waypoint", "speed": [0, 1]})",
                    "/ues/1/mobility/speed/0: must be positive, got 0"},
        BadMobility{R"({"model": "random_waypoint", "speed": [2, 1]})",
                    "/ues/1/mobility/speed: min must be below max"},
        BadMobility{R"({"model": "random_waypoint", "pause": -0.5})",
                    "/ues/1/mobility/pause: must not be negative, got -0.5"},
        BadMobility{R"({"model": "gauss_markov", "speed": 0})",
                    "/ues/1/mobility/speed: must be positive, got 0"},
        BadMobility{R"({"model": "gauss_markov", "alpha": 1.5})",
                    "/ues/1/mobility/alpha: must be <= 1, got 1.5"},
        BadMobility{R"({"model": "gauss_markov", "alpha": -0.1})",
                    "/ues/1/mobility/alpha: must not be negative, got -0.1"},
        BadMobility{R"({"model": "crowd"})",
                    "/ues/1/mobility/target: is required ([x, y]: where the crowd gathers)"},
        BadMobility{R"({"model": "crowd", "target": [50, 50]})",
                    "/ues/1/mobility/target: crowd target (50, 50) is inside building 0 "
                    "(\"hall\")"},
        BadMobility{R"({"model": "crowd", "target": [150, 50]})",
                    "/ues/1/mobility/target: crowd target (150, 50) is outside the venue [0, "
                    "100] x [0, 100]"},
        BadMobility{R"({"model": "crowd", "target": [20, 20], "speed": -2})",
                    "/ues/1/mobility/speed: must be positive, got -2"},
        BadMobility{R"({"model": "crowd", "target": [20, 20], "dwell": -1})",
                    "/ues/1/mobility/dwell: must not be negative, got -1"},
        BadMobility{R"({"model": "gauss_markov", "change_interval": 2})",
                    "/ues/1/mobility/change_interval: unknown key"}));

TEST(MobilityParser, AMobileUeStartsOnTheGround) {
  // On the roof of the hall (above its 20 m): fine standing still, not for walking.
  json doc = Doc();
  doc["ues"][1]["position"] = {50, 50, 25};
  EXPECT_EQ(ErrorOf(doc, {}), "");
  EXPECT_EQ(ErrorOf(doc, {R"(ues.1.mobility={"model": "random_waypoint"})"}),
            "/ues/1/position: UE \"ue1\" moves (random_waypoint) but starts on building 0 "
            "(\"hall\"): a mobile UE starts on the ground");
}

}  // namespace
}  // namespace rlpos
