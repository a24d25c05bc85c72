// Scenarios of several UAVs: "uavs", names, channels, fixed association, and their errors.
#include <gtest/gtest.h>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

json Campus() {
  return ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json");
}

TEST(MultiUavScenario, ShippedScenariosParse) {
  const Scenario campus = ParseScenario(Campus());
  ASSERT_EQ(campus.uavs.size(), 2u);
  EXPECT_EQ(campus.uavs[0].name, "north");
  EXPECT_EQ(campus.uavs[1].name, "south");
  EXPECT_EQ(campus.ues.size(), 12u);
  const Scenario urban = ParseScenario(
      ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/urban3.json"));
  EXPECT_EQ(urban.uavs.size(), 3u);
  EXPECT_EQ(urban.ues.size(), 20u);
}

TEST(MultiUavScenario, OneUavFormIsOneUavNamedUav) {
  const Scenario s =
      ParseScenario(ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json"));
  ASSERT_EQ(s.uavs.size(), 1u);
  EXPECT_EQ(s.uavs[0].name, "uav");
  EXPECT_EQ(s.UavPath(0), "/uav");
  // Its canonical document keeps the one-UAV form, as before names and channels existed.
  const json doc = ToJson(s);
  EXPECT_TRUE(doc.contains("uav"));
  EXPECT_FALSE(doc.contains("uavs"));
  EXPECT_FALSE(doc["uav"].contains("name"));
}

TEST(MultiUavScenario, ListRoundTripsWithChannelsAndFixedUes) {
  json doc = Campus();
  ApplyOverrides(doc, {"uavs.1.channel=50", "ues.3.uav=\"south\""});
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.uavs[0].channel, 0);  // assigned by the network (wifi.channel first)
  EXPECT_EQ(s.uavs[1].channel, 50);
  EXPECT_EQ(s.ues[3].uav, "south");
  EXPECT_EQ(s.UavIndex("south"), 1);
  EXPECT_EQ(s.UavIndex("east"), -1);
  const Scenario again = ParseScenario(ToJson(s));
  ASSERT_EQ(again.uavs.size(), 2u);
  EXPECT_EQ(again.uavs[1].channel, 50);
  EXPECT_EQ(again.uavs[1].name, "south");
  EXPECT_EQ(again.ues[3].uav, "south");
  EXPECT_EQ(again.UavPath(1), "/uavs/1");
}

TEST(MultiUavScenario, SpeedLimitsPerUavDefaultAndRoundTrip) {
  json doc = Campus();
  ApplyOverrides(doc, {"uavs.1.max_speed=4.5", "uavs.1.max_climb=1"});
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.uavs[0].max_speed, 10.0);  // the defaults
  EXPECT_EQ(s.uavs[0].max_climb, 3.0);
  EXPECT_EQ(s.uavs[1].max_speed, 4.5);
  EXPECT_EQ(s.uavs[1].max_climb, 1.0);
  const json written = ToJson(s);
  // Defaults are not written: documents from before the limits keep their bytes.
  EXPECT_FALSE(written["uavs"][0].contains("max_speed"));
  EXPECT_FALSE(written["uavs"][0].contains("max_climb"));
  const Scenario again = ParseScenario(written);
  EXPECT_EQ(again.uavs[1].max_speed, 4.5);
  EXPECT_EQ(again.uavs[1].max_climb, 1.0);
}

TEST(MultiUavScenario, UnnamedUavsAreNumbered) {
  json doc = Campus();
  doc["uavs"][0].erase("name");
  doc["uavs"][1].erase("name");
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.uavs[0].name, "uav1");
  EXPECT_EQ(s.uavs[1].name, "uav2");
}

struct BadInput {
  const char* name;
  std::vector<std::string> overrides;
  const char* error;
};

class MultiUavBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(MultiUavBadInput, NamesPathAndProblem) {
  const std::string error = ErrorOf(Campus(), GetParam().overrides);
  EXPECT_EQ(error.rfind(GetParam().error, 0), 0u) << "got: " << error;
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(
    Cases, MultiUavBadInput,
    ::testing::Values(
        BadInput{"BothForms", {"uav={\"position\": [10, 10, 10]}"}, "/uavs: give \"uav\" (one UAV) or \"uavs\", not both"},
        BadInput{"EmptyList", {"uavs=[]"}, "/uavs: expected a non-empty array of UAVs"},
        BadInput{"TooMany", {"uavs=[{},{},{},{},{},{},{},{},{}]"}, "/uavs: 9 UAVs; at most 8 are supported"},
        BadInput{"Overlap", {"uavs.1.position=[80.5, 90, 12]"}, "/uavs/1/position: UAV \"south\" at (80.5, 90, 12) overlaps UAV 0 (\"north\") at (80, 90, 12): UAVs must be at least 1 m apart"},
        BadInput{"InsideBuilding", {"uavs.1.position=[80, 50, 10]"}, "/uavs/1/position: UAV at (80, 50, 10) is inside building 0 (\"library\")"},
        BadInput{"OutsideItsZone", {"uavs.0.zone.z=[20, 60]"}, "/uavs/0/zone: the zone [0, 160] x [0, 100] x [20, 60] excludes the initial position (80, 90, 12)"},
        BadInput{"SameName", {"uavs.1.name=\"north\""}, "/uavs/1/name: UAV 0 has the name \"north\" already"},
        BadInput{"EmptyName", {"uavs.1.name=\"\""}, "/uavs/1/name: must not be empty"},
        BadInput{"BadChannel", {"uavs.1.channel=0"}, "/uavs/1/channel: must be in [1, 233]"},
        BadInput{"StillSpeed", {"uavs.1.max_speed=0"}, "/uavs/1/max_speed: must be positive, got 0"},
        BadInput{"NegativeClimb", {"uavs.0.max_climb=-3"}, "/uavs/0/max_climb: must be positive, got -3"},
        BadInput{"SpeedBeyondBound", {"uavs.1.max_speed=101"}, "/uavs/1/max_speed: must be <= 100, got 101"},
        BadInput{"UnknownKey", {"uavs.1.chanel=36"}, "/uavs/1/chanel: unknown key \"chanel\"; did you mean \"channel\"?"},
        BadInput{"UeFixedToNobody", {"ues.2.uav=\"east\""}, "/ues/2/uav: no UAV is named \"east\" (UAVs: \"north\" \"south\")"}),
    [](const ::testing::TestParamInfo<BadInput>& param) { return param.param.name; });
// clang-format on

}  // namespace
}  // namespace rlpos
