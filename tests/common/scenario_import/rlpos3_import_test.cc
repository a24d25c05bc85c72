// The full RLpos-3 config of data/ imports into the scenario its fields describe.
#include "common/scenario_import/rlpos3_import.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/common/scenario_import/rlpos3_config.h"

namespace rlpos {
namespace {

void ExpectAt(const Vec3& p, double x, double y, double z) {
  EXPECT_DOUBLE_EQ(p.x, x);
  EXPECT_DOUBLE_EQ(p.y, y);
  EXPECT_DOUBLE_EQ(p.z, z);
}

class Rlpos3Import : public ::testing::Test {
 protected:
  ImportResult result = ImportRlpos3(FullRlpos3Config(), "full");
  const Scenario& s = result.scenario;

  // The warning at `path` ("" when there is none).
  std::string WarningAt(const std::string& path) const {
    for (const auto& w : result.warnings) {
      if (w.path == path)
        return w.message;
    }
    return "";
  }
};

// venueSize [-60, 40] x [-20, 80] x [10, 70]: x + 60, y + 20, z as it is (the ground is z 0).
TEST_F(Rlpos3Import, VenueAndZoneFromVenueSize) {
  EXPECT_DOUBLE_EQ(s.venue.width, 100);
  EXPECT_DOUBLE_EQ(s.venue.depth, 100);
  EXPECT_DOUBLE_EQ(s.venue.height, 80);  // building 2 rises to 80 m, above Zmax
  ASSERT_EQ(s.uavs.size(), 1u);
  ExpectAt(s.uavs[0].initial, 50, 50, 20);
  const Box& zone = s.uavs[0].zone;
  EXPECT_EQ(std::vector<double>({zone.xmin, zone.xmax, zone.ymin, zone.ymax, zone.zmin, zone.zmax}),
            std::vector<double>({0, 100, 0, 100, 10, 70}));
  EXPECT_DOUBLE_EQ(s.env.step, 2);  // gridResolution
}

TEST_F(Rlpos3Import, UesMoveIntoTheVenueFrame) {
  ASSERT_EQ(s.ues.size(), 4u);
  ExpectAt(s.ues[0].position, 10, 10, 1.5);
  ExpectAt(s.ues[1].position, 90, 90, 1.5);
  ExpectAt(s.ues[2].position, 40, 60, 1.5);
  ExpectAt(s.ues[3].position, 60, 20, 1.5);
}

TEST_F(Rlpos3Import, BuildingsStandOnTheGround) {
  ASSERT_EQ(s.buildings.size(), 3u);
  const BuildingSpec& b = s.buildings[0];
  EXPECT_EQ(std::vector<double>({b.xmin, b.xmax, b.ymin, b.ymax, b.height}),
            std::vector<double>({20, 30, 30, 50, 25}));
  EXPECT_EQ(std::vector<int>({b.floors, b.rooms_x, b.rooms_y}), std::vector<int>({6, 2, 4}));
  const BuildingSpec& raised = s.buildings[1];  // zmin 2 in the source
  EXPECT_EQ(
      std::vector<double>({raised.xmin, raised.xmax, raised.ymin, raised.ymax, raised.height}),
      std::vector<double>({70, 90, 60, 70, 12}));
  EXPECT_NE(WarningAt("/ns3Sim/defaultValues/Buildings/1/BuildingPosition").find("zmin 2"),
            std::string::npos);
}

// 802.11ac, 80 MHz, GI 400 ns: MCS 0..9 carry 32.5, 65, 97.5, 130, ... 433.33 Mbit/s.
TEST_F(Rlpos3Import, DataRatesBecomeMcsDemands) {
  EXPECT_EQ(s.ues[0].demand_mcs, 0);  // "32.5Mbps": exactly MCS 0
  EXPECT_EQ(s.ues[1].demand_mcs, 1);  // "50Mbps": rounded up
  EXPECT_DOUBLE_EQ(s.ues[1].demand_mbps, 65);
  EXPECT_EQ(s.ues[2].demand_mcs, 3);   // "16250KBps" = 130 Mbit/s: exactly MCS 3
  EXPECT_EQ(s.ues[3].demand_mcs, -1);  // "500Mbps": above MCS 9, kept in Mbit/s
  EXPECT_DOUBLE_EQ(s.ues[3].demand_mbps, 500);
  EXPECT_EQ(WarningAt("/ns3Sim/defaultValues/UENodes/0/DataRate"), "");
  EXPECT_EQ(WarningAt("/ns3Sim/defaultValues/UENodes/1/DataRate"),
            "50 Mbit/s rounded up to MCS 1 (65 Mbit/s, 802.11ac, 80 MHz, GI 400 ns): the UE offers "
            "that rate");
  EXPECT_EQ(WarningAt("/ns3Sim/defaultValues/UENodes/2/DataRate"), "");
  EXPECT_EQ(WarningAt("/ns3Sim/defaultValues/UENodes/3/DataRate"),
            "500 Mbit/s is above the top MCS 9 (433.33 Mbit/s, 802.11ac, 80 MHz, GI 400 ns): kept "
            "in Mbit/s, a demand no MCS meets");
}

TEST_F(Rlpos3Import, RadioAndRunSettings) {
  EXPECT_EQ(s.wifi.standard, "802.11ac");
  EXPECT_EQ(s.wifi.width_mhz, 80);
  EXPECT_EQ(s.wifi.guard_interval_ns, 400);
  EXPECT_EQ(s.wifi.channel, 42);
  EXPECT_DOUBLE_EQ(s.wifi.noise_floor_dbm, -88);
  EXPECT_DOUBLE_EQ(s.wifi.antenna_gain_dbi, 2.5);
  EXPECT_DOUBLE_EQ(s.wifi.tx_power_dbm, 17);
  EXPECT_EQ(s.wifi.rate_manager.type, "ns3::MinstrelHtWifiManager");  // "min"
  EXPECT_EQ(s.traffic.protocol, "tcp_bulk");
  EXPECT_EQ(s.simulation.seed, 3u);
  EXPECT_EQ(s.simulation.run, 7u);
  EXPECT_DOUBLE_EQ(s.env.decision_interval, 0.2);
  EXPECT_DOUBLE_EQ(s.env.episode_duration, 60);  // simDuration
  // left/right along y, back/front along x, down/up, same
  EXPECT_EQ(s.env.actions, std::vector<std::string>(
                               {"backward", "forward", "down", "up", "left", "right", "stay"}));
}

TEST_F(Rlpos3Import, AgentHyperparameters) {
  EXPECT_EQ(s.agent.algorithm, "dqn");
  EXPECT_EQ(s.agent.hidden, std::vector<int>({128, 64}));
  EXPECT_EQ(s.agent.eval_episodes, 2);
  EXPECT_EQ(s.agent.train_episodes, 5);
  // RLpos-3's episodes are whole ones from the start, without checkpoints.
  EXPECT_EQ(s.agent.train_episode_steps, 0);
  EXPECT_FALSE(s.agent.exploring_starts);
  EXPECT_EQ(s.agent.eval_interval, 0);
  EXPECT_EQ(s.agent.dqn.replay_capacity, 50000);
  EXPECT_EQ(s.agent.dqn.batch_size, 32);
  EXPECT_DOUBLE_EQ(s.agent.dqn.learning_rate, 0.005);
  EXPECT_DOUBLE_EQ(s.agent.dqn.gamma, 0.8);
  EXPECT_DOUBLE_EQ(s.agent.dqn.epsilon_start, 1.0);
  EXPECT_EQ(s.agent.dqn.epsilon_decay_steps, 4000);
  EXPECT_DOUBLE_EQ(s.agent.dqn.epsilon_end, 0.1);
}

// One warning per field not carried as it was, in a fixed order.
TEST_F(Rlpos3Import, EveryFieldNotCarriedIsNamed) {
  std::vector<std::string> paths;
  for (const auto& w : result.warnings)
    paths.push_back(w.path);
  const std::string ue = "/ns3Sim/defaultValues/UENodes/";
  EXPECT_EQ(paths, std::vector<std::string>({"/StartScript",
                                             "/Gym/logLevels",
                                             "/Gym/bypass",
                                             "/ns3Sim/logLevels",
                                             "/ns3Sim/configSim/fixedMCS",
                                             "/ns3Sim/configSim/htDataRates",
                                             "/ns3Sim/configSim/vhtDataRates",
                                             "/ns3Sim/configSim/enableGym",
                                             "/ns3Sim/configSim/path",
                                             "/ns3Sim/defaultValues/openGymPort",
                                             "/ns3Sim/defaultValues/Buildings/1/BuildingPosition",
                                             ue + "0/SNR",
                                             ue + "1/DataRate",
                                             ue + "1/SNR",
                                             ue + "2/SNR",
                                             ue + "3/DataRate",
                                             ue + "3/SNR",
                                             "/Agent/simType",
                                             "/Agent/newPolicy",
                                             "/Agent/dir",
                                             "/Agent/logSteps",
                                             "/Agent/actionDebug",
                                             "/Agent/debugLevel",
                                             "/experiment"}));
  EXPECT_NE(WarningAt("/experiment").find("not carried"), std::string::npos);
}

// The result is a scenario our parser takes back unchanged, and the same config gives the
// same bytes.
TEST_F(Rlpos3Import, ValidatesAndIsDeterministic) {
  const std::string text = ToJson(s).dump(2);
  EXPECT_EQ(ToJson(ParseScenario(nlohmann::json::parse(text))).dump(2), text);
  EXPECT_EQ(ToJson(ImportRlpos3(FullRlpos3Config(), "full").scenario).dump(2), text);
}

// "fixed": ns-3's ConstantRateWifiManager at entry fixedMCS of the standard's mode list.
TEST(Rlpos3ImportVariants, FixedRateManager) {
  nlohmann::json config = FullRlpos3Config();
  config["ns3Sim"]["configSim"]["RemotStManager"] = "fixed";
  const ImportResult r = ImportRlpos3(config, "fixed");
  EXPECT_EQ(r.scenario.wifi.rate_manager.type, "ns3::ConstantRateWifiManager");
  EXPECT_EQ(r.scenario.wifi.rate_manager.attributes,
            nlohmann::json({{"DataMode", "VhtMcs2"}, {"ControlMode", "VhtMcs2"}}));
  const auto warned = [&](const std::string& path) {
    return std::any_of(r.warnings.begin(), r.warnings.end(),
                       [&](const ImportWarning& w) { return w.path == path; });
  };
  EXPECT_TRUE(warned("/ns3Sim/configSim/htDataRates"));  // 802.11n's list
  EXPECT_FALSE(warned("/ns3Sim/configSim/vhtDataRates"));
  EXPECT_FALSE(warned("/ns3Sim/configSim/fixedMCS"));
}

// Two UAVNodes become uavs[]; a Zmin below the ground starts the zone at the ground.
TEST(Rlpos3ImportVariants, SeveralUavsAndZminBelowTheGround) {
  nlohmann::json config = FullRlpos3Config();
  config["ns3Sim"]["defaultValues"]["UAVNodes"].push_back({{"positionVector", {20, 10, 30}}});
  config["Gym"]["venueSize"]["Zmin"] = -5;
  const ImportResult r = ImportRlpos3(config, "two");
  ASSERT_EQ(r.scenario.uavs.size(), 2u);
  EXPECT_TRUE(r.scenario.uavs_listed);
  EXPECT_EQ(r.scenario.uavs[1].name, "uav2");
  EXPECT_DOUBLE_EQ(r.scenario.uavs[1].initial.x, 80);
  EXPECT_DOUBLE_EQ(r.scenario.uavs[1].initial.y, 30);
  EXPECT_DOUBLE_EQ(r.scenario.uavs[1].zone.zmin, 0);
  std::vector<std::string> paths;
  for (const auto& w : r.warnings)
    paths.push_back(w.path);
  EXPECT_NE(std::find(paths.begin(), paths.end(), "/Gym/venueSize/Zmin"), paths.end());
  EXPECT_NE(std::find(paths.begin(), paths.end(), "/ns3Sim/defaultValues/UAVNodes"), paths.end());
}

TEST(Rlpos3SourcePath, NamesTheFieldTheUserWrote) {
  EXPECT_EQ(Rlpos3SourcePath("/ues/3/position/1"),
            "/ns3Sim/defaultValues/UENodes/3/positionVector/1");
  EXPECT_EQ(Rlpos3SourcePath("/ues/2/demand/mbps"), "/ns3Sim/defaultValues/UENodes/2/DataRate");
  EXPECT_EQ(Rlpos3SourcePath("/buildings/4/x"),
            "/ns3Sim/defaultValues/Buildings/4/BuildingPosition");
  EXPECT_EQ(Rlpos3SourcePath("/uav/zone"), "/Gym/venueSize");
  EXPECT_EQ(Rlpos3SourcePath("/uavs/1/position"),
            "/ns3Sim/defaultValues/UAVNodes/1/positionVector");
  EXPECT_EQ(Rlpos3SourcePath("/wifi/noise_floor"), "/ns3Sim/defaultValues/PN");
  EXPECT_EQ(Rlpos3SourcePath("/agent/gamma"), "/Agent/hyperParameters/discount");
  EXPECT_EQ(Rlpos3SourcePath("/env/actions/2"), "/ns3Sim/configSim/UAV_directions/2");
  EXPECT_EQ(Rlpos3SourcePath("/propagation/type"), "/propagation/type");  // not from the source
}

}  // namespace
}  // namespace rlpos
