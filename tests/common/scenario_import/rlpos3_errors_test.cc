// Bad RLpos-3 configs: one error naming the field the user wrote, and no scenario.
#include <gtest/gtest.h>

#include "tests/common/scenario_import/rlpos3_config.h"

namespace rlpos {
namespace {

using nlohmann::json;

const std::string kDefaults = "/ns3Sim/defaultValues";

// The full config with `edit` applied at the JSON pointer `path`.
json With(const std::string& path, const json& value) {
  json config = FullRlpos3Config();
  config[json::json_pointer(path)] = value;
  return config;
}

json Without(const std::string& path) {
  json config = FullRlpos3Config();
  const json::json_pointer pointer(path);
  config[pointer.parent_pointer()].erase(pointer.back());
  return config;
}

TEST(Rlpos3Errors, MissingKeys) {
  EXPECT_EQ(ImportErrorOf(Without("/Gym/venueSize/Xmin")),
            "/Gym/venueSize/Xmin: is required (a number)");
  EXPECT_EQ(ImportErrorOf(Without("/Gym/venueSize")),
            "/Gym/venueSize: is required (Xmin, Xmax, Ymin, Ymax, Zmin, Zmax)");
  EXPECT_EQ(ImportErrorOf(Without("/ns3Sim/defaultValues")),
            "/ns3Sim/defaultValues: is required (UENodes, UAVNodes, Buildings, radio)");
  EXPECT_EQ(ImportErrorOf(Without(kDefaults + "/UENodes/2/DataRate")),
            kDefaults + "/UENodes/2/DataRate: is required (an ns-3 DataRate such as \"58.5Mbps\")");
  EXPECT_EQ(ImportErrorOf(Without(kDefaults + "/UAVNodes/0/positionVector")),
            kDefaults + "/UAVNodes/0/positionVector: is required ([x, y, z])");
  EXPECT_EQ(ImportErrorOf(Without(kDefaults + "/Buildings/1/BuildingPosition")),
            kDefaults +
                "/Buildings/1/BuildingPosition: is required ([xmin, xmax, ymin, ymax, zmin, zmax, "
                "floors, rooms x, rooms y])");
}

TEST(Rlpos3Errors, BuildingWithXminAboveXmax) {
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/Buildings/0/BuildingPosition",
                               {-30.0, -40.0, 10.0, 30.0, 0.0, 25.0, 6, 2, 4})),
            kDefaults + "/Buildings/0/BuildingPosition: xmin (-30) must be below xmax (-40)");
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/Buildings/0/BuildingPosition",
                               {-40.0, -30.0, 10.0, 30.0, 0.0, 25.0, 6, 2})),
            kDefaults +
                "/Buildings/0/BuildingPosition: expected [xmin, xmax, ymin, ymax, zmin, zmax, "
                "floors, rooms x, rooms y] (9 numbers), got 8 entries");
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/Buildings/0/BuildingPosition/6", 2.5)),
            kDefaults + "/Buildings/0/BuildingPosition/6: expected an integer, got 2.5");
}

TEST(Rlpos3Errors, UeInsideABuilding) {
  // Building 0 covers x [-40, -30], y [10, 30], z [0, 25].
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/UENodes/2/positionVector", {-35.0, 20.0, 1.5})),
            kDefaults +
                "/UENodes/2/positionVector: UE at (-35, 20, 1.5) is inside the building "
                "/ns3Sim/defaultValues/Buildings/0");
}

TEST(Rlpos3Errors, NegativeOrUnreadableDataRate) {
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/UENodes/1/DataRate", "-5Mbps")),
            kDefaults + "/UENodes/1/DataRate: negative data rate \"-5Mbps\"");
  EXPECT_EQ(
      ImportErrorOf(With(kDefaults + "/UENodes/1/DataRate", 50)),
      kDefaults + "/UENodes/1/DataRate: expected a string such as \"58.5Mbps\", got a number");
}

TEST(Rlpos3Errors, OutsideTheVenue) {
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/UENodes/0/positionVector", {50.0, 0.0, 1.5})),
            kDefaults +
                "/UENodes/0/positionVector: UE at (50, 0, 1.5) lies outside Gym.venueSize "
                "[-60, 40] x [-20, 80]");
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/UAVNodes/0/positionVector", {0, 0, 5})),
            kDefaults +
                "/UAVNodes/0/positionVector/2: UAV altitude 5 is outside Gym.venueSize's "
                "Zmin..Zmax [10, 70]");
  EXPECT_EQ(ImportErrorOf(With("/Gym/venueSize/Xmax", -60)),
            "/Gym/venueSize/Xmax: must be above its min (-60), got -60");
}

TEST(Rlpos3Errors, UnknownValues) {
  EXPECT_EQ(ImportErrorOf(With("/ns3Sim/configSim/RemotStManager", "aarf")),
            "/ns3Sim/configSim/RemotStManager: unknown value \"aarf\" (expected \"fixed\", "
            "\"id\", \"min\")");
  EXPECT_EQ(ImportErrorOf(With("/ns3Sim/configSim/UAV_directions/1", "sideways")),
            "/ns3Sim/configSim/UAV_directions/1: unknown move \"sideways\" (expected left, right, "
            "back, front, down, up or same)");
  EXPECT_EQ(ImportErrorOf(With(kDefaults + "/channelBW", 60)),
            kDefaults + "/channelBW: 60 MHz is not a channel width of 802.11ac");
}

// What only our parser sees is reported at the source's field too.
TEST(Rlpos3Errors, ScenarioChecksNameTheSourceField) {
  json config = FullRlpos3Config();
  config["ns3Sim"]["defaultValues"]["Buildings"][2]["BuildingPosition"] =
      json::array({-38.0, -28.0, 20.0, 40.0, 0.0, 10.0, 1, 1, 1});  // overlaps building 0
  EXPECT_EQ(ImportErrorOf(config), kDefaults +
                                       "/Buildings/2/BuildingPosition: building \"building2\" "
                                       "overlaps building 0 (\"building0\") (as the scenario's "
                                       "/buildings/2)");
  EXPECT_EQ(ImportErrorOf(With("/Agent/hyperParameters/discount", 1.5)),
            "/Agent/hyperParameters/discount: must be <= 1, got 1.5 (as the scenario's "
            "/agent/gamma)");
}

TEST(Rlpos3Errors, NotAnObject) {
  EXPECT_EQ(ImportErrorOf(json::array()), "/: expected an object, got an array");
  EXPECT_EQ(ImportErrorOf(With("/Gym", 3)), "/Gym: expected an object, got a number");
}

}  // namespace
}  // namespace rlpos
