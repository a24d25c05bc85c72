#include "common/scenario/scenario_parser.h"

#include <gtest/gtest.h>

#include "common/config/config_error.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

TEST(ScenarioParser, ShippedScenariosParse) {
  for (const char* name : {"a", "b", "c"}) {
    const Scenario s = ParseScenario(
        ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json"));
    EXPECT_FALSE(s.ues.empty()) << name;
  }
}

TEST(ScenarioParser, DefaultsAreThePapersTableOne) {
  const Scenario s = ParseScenario(json::parse(R"({"ues": [{"position": [10, 10, 1.5],
                                                   "demand": {"mcs": 0}}]})"));
  EXPECT_EQ(s.wifi.standard, "802.11ac");
  EXPECT_EQ(s.wifi.channel, 50);
  EXPECT_EQ(s.wifi.width_mhz, 160);
  EXPECT_EQ(s.wifi.guard_interval_ns, 800);
  EXPECT_DOUBLE_EQ(s.wifi.tx_power_dbm, 20.0);
  EXPECT_DOUBLE_EQ(s.wifi.antenna_gain_dbi, 0.0);
  EXPECT_DOUBLE_EQ(s.wifi.noise_floor_dbm, -85.0);
  EXPECT_EQ(s.wifi.rate_manager.type, "ns3::IdealWifiManager");
  EXPECT_EQ(s.traffic.protocol, "udp_cbr");
  EXPECT_EQ(s.traffic.packet_size, 1400);
  EXPECT_EQ(s.propagation.type, "ns3::ObstacleAwarePropagationLossModel");
  EXPECT_EQ(s.propagation.attributes["LosModel"]["type"], "ns3::ItuR1411LosPropagationLossModel");
  EXPECT_DOUBLE_EQ(s.ues[0].demand_mbps, 58.5);
  EXPECT_DOUBLE_EQ(s.venue.width, 100.0);
}

TEST(ScenarioParser, DemandsOfScenarioC) {
  const Scenario s =
      ParseScenario(ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/c.json"));
  ASSERT_EQ(s.ues.size(), 4u);
  EXPECT_DOUBLE_EQ(s.ues[0].demand_mbps, 234.0);
  EXPECT_DOUBLE_EQ(s.ues[1].demand_mbps, 175.5);
  EXPECT_DOUBLE_EQ(s.ues[2].demand_mbps, 117.0);
  EXPECT_DOUBLE_EQ(s.ues[3].demand_mbps, 58.5);
}

TEST(ScenarioParser, OverridesSetAnyField) {
  json doc = ShippedScenarioDocument("b");
  ApplyOverrides(doc, {"wifi.mode=adhoc", "/simulation/run=7", "ues.1.demand={\"mbps\": 10}",
                       "uav.position=[50, 35, 10]"});
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.wifi.mode, "adhoc");
  EXPECT_EQ(s.simulation.run, 7u);
  EXPECT_DOUBLE_EQ(s.ues[1].demand_mbps, 10.0);
  EXPECT_DOUBLE_EQ(s.uavs[0].initial.y, 35.0);
}

TEST(ScenarioParser, AlgorithmOverridesSelectTheAgentAndItsActionSpace) {
  json doc = ShippedScenarioDocument("b");
  ApplyOverrides(doc, AlgorithmOverrides("sac"));
  ApplyOverrides(doc, {"agent.sac.alpha=0.1", "agent.ppo.epochs=3", "agent.eval_interval=10",
                       "agent.ppo.anneal_learning_rate=true"});
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.agent.algorithm, "sac");
  EXPECT_EQ(s.env.action_space, "continuous");
  EXPECT_EQ(s.agent.sac.alpha, 0.1);
  EXPECT_EQ(s.agent.ppo.epochs, 3);
  EXPECT_EQ(s.agent.eval_interval, 10);
  EXPECT_TRUE(s.agent.ppo.anneal_learning_rate);
  EXPECT_EQ(ToJson(ParseScenario(ToJson(s))), ToJson(s));  // the sections round-trip
  json back = ToJson(s);
  ApplyOverrides(back, AlgorithmOverrides("ppo"));
  EXPECT_EQ(ParseScenario(back).env.action_space, "discrete");
}

// agent.ue_encoder: read, written back, and absent from a document that does not set it (whose
// bytes, and so the ids of its jobs and checkpoints, stay as they were).
TEST(ScenarioParser, TheUeEncoderIsWrittenOnlyWhereSet) {
  json doc = ShippedScenarioDocument("b");
  EXPECT_FALSE(ToJson(ParseScenario(doc))["agent"].contains("ue_encoder"));
  ApplyOverrides(doc, {"agent.algorithm=ppo", "env.observations=[\"zone\", \"ues\"]",
                       "agent.ue_encoder=[32, 16]"});
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.agent.ue_encoder, (std::vector<int>{32, 16}));
  EXPECT_EQ(ToJson(s)["agent"]["ue_encoder"], json({32, 16}));
  EXPECT_EQ(ParseScenario(ToJson(s)).agent.ue_encoder, s.agent.ue_encoder);
  ApplyOverrides(doc, {"agent.ue_encoder=[]"});
  EXPECT_TRUE(ParseScenario(doc).agent.ue_encoder.empty());
}

TEST(ScenarioParser, TrainingDefaultsFollowTheAlgorithmAndTheUavCount) {
  const auto agent_of = [](const std::string& file, const std::string& algorithm,
                           std::vector<std::string> overrides) {
    json doc = ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + file);
    ApplyOverrides(doc, AlgorithmOverrides(algorithm));
    ApplyOverrides(doc, overrides);
    return ParseScenario(doc).agent;
  };
  const AgentSpec dqn = agent_of("b.json", "dqn", {});
  EXPECT_EQ(dqn.train_episodes, 1000);
  EXPECT_EQ(dqn.train_episode_steps, 25);
  EXPECT_EQ(dqn.eval_interval, 50);
  EXPECT_TRUE(dqn.exploring_starts);
  EXPECT_EQ(dqn.baseline_start_every, 0);
  EXPECT_EQ(ParseScenario(ShippedScenarioDocument("b")).agent.train_episodes,
            1000);  // no agent section: dqn's
  const AgentSpec ppo = agent_of("b.json", "ppo", {});
  EXPECT_EQ(ppo.train_episodes, 4000);
  EXPECT_EQ(ppo.eval_interval, 100);
  EXPECT_EQ(ppo.baseline_start_every, 4);
  const AgentSpec sac = agent_of("b.json", "sac", {});
  EXPECT_EQ(sac.train_episodes, 2500);
  EXPECT_EQ(sac.train_episode_steps, 10);
  EXPECT_EQ(sac.baseline_start_every, 4);
  // Two UAVs: 1.5 times one UAV's episodes; three: twice.
  EXPECT_EQ(agent_of("campus2.json", "dqn", {}).train_episodes, 1500);
  EXPECT_EQ(agent_of("urban3.json", "ppo", {}).train_episodes, 8000);
  // A value the scenario gives is kept as it is, whatever the algorithm and UAV count.
  const AgentSpec set =
      agent_of("urban3.json", "sac", {"agent.train_episodes=7", "agent.train_episode_steps=0"});
  EXPECT_EQ(set.train_episodes, 7);
  EXPECT_EQ(set.train_episode_steps, 0);
  EXPECT_EQ(set.eval_interval, 100);
}

TEST(ScenarioParser, SacHasItsOwnReplayAndStillReadsTheOneItUsedToShareWithDqn) {
  const auto agent_of = [](const std::string& algorithm, std::vector<std::string> overrides) {
    json doc = ShippedScenarioDocument("b");
    ApplyOverrides(doc, AlgorithmOverrides(algorithm));
    ApplyOverrides(doc, overrides);
    return ParseScenario(doc).agent;
  };
  EXPECT_EQ(agent_of("sac", {}).sac.replay_capacity, 1000000);
  EXPECT_EQ(agent_of("sac", {"agent.sac.replay_capacity=7000"}).sac.replay_capacity, 7000);
  // SAC's replay read agent.replay_capacity before it had its own: such a scenario keeps it.
  const AgentSpec old_key = agent_of("sac", {"agent.replay_capacity=5000"});
  EXPECT_EQ(old_key.sac.replay_capacity, 5000);
  EXPECT_EQ(agent_of("sac", {"agent.replay_capacity=5000", "agent.sac.replay_capacity=7000"})
                .sac.replay_capacity,
            7000);
  // DQN's is DQN's: another algorithm's replay does not move with it.
  const AgentSpec dqn = agent_of("dqn", {"agent.replay_capacity=5000"});
  EXPECT_EQ(dqn.dqn.replay_capacity, 5000);
  EXPECT_EQ(dqn.sac.replay_capacity, 1000000);
  EXPECT_EQ(agent_of("dqn", {"agent.sac.replay_capacity=7000"}).dqn.replay_capacity, 1000000);
  // The effective scenario names SAC's own, and reads back the same.
  json doc = ShippedScenarioDocument("b");
  ApplyOverrides(doc, AlgorithmOverrides("sac"));
  ApplyOverrides(doc, {"agent.replay_capacity=5000"});
  const json written = ToJson(ParseScenario(doc));
  EXPECT_EQ(written.at("agent").at("sac").at("replay_capacity"), 5000);
  EXPECT_EQ(ParseScenario(written).agent.sac.replay_capacity, 5000);
}

TEST(ScenarioParser, ToJsonRoundTrips) {
  const Scenario s = ParseScenario(ShippedScenarioDocument("b"));
  const Scenario again = ParseScenario(ToJson(s));
  EXPECT_EQ(ToJson(again), ToJson(s));
}

TEST(ScenarioParser, MalformedJsonNamesLineAndColumn) {
  try {
    ParseJsonText("{\n  \"venue\": {\"width\": 100,,}\n}");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(e.problem().find("malformed JSON at line 2"), std::string::npos) << e.problem();
  }
}

// An error about the file itself names no JSON path ("/"), but the system's reason: callers
// prefix the file, "d.json: cannot open: No such file or directory".
TEST(ScenarioParser, MissingFileIsAConfigErrorWithTheSystemsReason) {
  try {
    ReadJsonFile("/nonexistent/scenario.json");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(), "cannot open: No such file or directory");
  }
  try {
    ReadJsonFile(RLPOS_SOURCE_DIR);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.describe(), "is a folder, not a JSON file");
  }
}

struct BadOverride {
  const char* name;
  std::vector<std::string> overrides;
  const char* expected;  // "<path>: <start of problem>"
};

class ScenarioParserBadInput : public ::testing::TestWithParam<BadOverride> {};

TEST_P(ScenarioParserBadInput, NamesPathAndProblem) {
  const std::string error = ErrorOf(ShippedScenarioDocument("b"), GetParam().overrides);
  EXPECT_NE(error.find(GetParam().expected), std::string::npos)
      << "got: \"" << error << "\", expected to contain: \"" << GetParam().expected << "\"";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ScenarioParserBadInput,
    ::testing::Values(
        BadOverride{
            "UnknownTopLevelKey", {"wfi={}"}, "/wfi: unknown key \"wfi\"; did you mean \"wifi\"?"},
        BadOverride{"UnknownNestedKey",
                    {"venue.widht=3"},
                    "/venue/widht: unknown key \"widht\"; did you mean \"width\"?"},
        BadOverride{
            "WrongType", {"venue.width=\"wide\""}, "/venue/width: expected a number, got a string"},
        BadOverride{"NegativeNumber", {"wifi.tx_power=-100"}, "/wifi/tx_power: must be >= -30"},
        BadOverride{"NegativeDuration",
                    {"simulation.duration=-1"},
                    "/simulation/duration: must be positive"},
        BadOverride{
            "FractionalInteger", {"wifi.channel=50.5"}, "/wifi/channel: expected an integer"},
        BadOverride{
            "UnknownEnum",
            {"wifi.mode=adhok"},
            "/wifi/mode: unknown value \"adhok\" (one of: adhoc, ap_sta); did you mean \"adhoc\"?"},
        BadOverride{"BadWidth", {"wifi.width=100"}, "/wifi/width: must be 20, 40, 80 or 160 MHz"},
        BadOverride{"BadGuardInterval",
                    {"wifi.guard_interval=1600"},
                    "/wifi/guard_interval: 802.11ac guard interval must be 400 or 800 ns"},
        BadOverride{"NoiseBelowThermal",
                    {"wifi.noise_floor=-100"},
                    "/wifi/noise_floor: is below the thermal noise"},
        BadOverride{"UeOutsideVenue",
                    {"ues.2.position=[130, 50, 1.5]"},
                    "/ues/2/position: UE at (130, 50, 1.5) is outside the venue"},
        BadOverride{"UeInsideBuilding",
                    {"ues.0.position=[50, 50, 1.5]"},
                    "/ues/0/position: UE at (50, 50, 1.5) is inside building 0 (\"tower\")"},
        BadOverride{
            "PositionNotTriple", {"ues.0.position=[1, 2]"}, "/ues/0/position: expected [x, y, z]"},
        BadOverride{"DemandBothForms",
                    {"ues.0.demand={\"mbps\": 1, \"mcs\": 0}"},
                    "/ues/0/demand: give exactly one of"},
        BadOverride{"DemandMcsTooHigh",
                    {"ues.0.demand={\"mcs\": 10}"},
                    "/ues/0/demand/mcs: must be in [0, 9]"},
        BadOverride{"BuildingOutsideVenue",
                    {"buildings.1.x=[90, 110]"},
                    "/buildings/1: building \"north-block\" [90, 110]"},
        BadOverride{
            "BuildingTooTall", {"buildings.0.height=80"}, "/buildings/0: building \"tower\""},
        BadOverride{"OverlappingBuildings",
                    {"buildings.4.x=[40, 50]", "buildings.4.y=[40, 50]"},
                    "/buildings/4: building \"west-house\" overlaps building 0 (\"tower\")"},
        BadOverride{
            "EmptyInterval", {"buildings.0.x=[55, 45]"}, "/buildings/0/x: min must be below max"},
        BadOverride{
            "ZoneExcludesInitial",
            {"uav.zone.z=[30, 60]"},
            "/uav/zone: the zone [0, 100] x [0, 100] x [30, 60] excludes the initial position "
            "(50, 50, 25)"},
        BadOverride{"UavInsideBuilding",
                    {"uav.position=[50, 50, 10]"},
                    "/uav/position: UAV at (50, 50, 10) is inside building 0"},
        BadOverride{"ZoneOutsideVenue",
                    {"uav.zone.x=[-10, 100]"},
                    "/uav/zone: the zone reaches outside the venue"},
        BadOverride{"WarmupTooLong",
                    {"simulation.warmup=20"},
                    "/simulation/warmup: must be shorter than the duration"},
        BadOverride{"NoUes", {"ues=[]"}, "/ues: expected a non-empty array"},
        BadOverride{"SpecWithoutType",
                    {"propagation={\"attributes\": {}}"},
                    "/propagation/type: is required"},
        BadOverride{"SpecBadAttributeValue",
                    {"propagation.attributes.Frequency=[1]"},
                    "/propagation/attributes/Frequency: expected a number, string, boolean"},
        BadOverride{"BadOverride", {"novalue"}, "--set novalue: expected path=value"},
        BadOverride{"UnknownAlgorithm",
                    {"agent.algorithm=a2c"},
                    "/agent/algorithm: unknown value \"a2c\" (one of: dqn, ppo, sac)"},
        BadOverride{
            "SacOnDiscreteMoves",
            {"agent.algorithm=sac"},
            "/agent/algorithm: sac needs env.action_space \"continuous\", not \"discrete\""},
        BadOverride{"DqnOnDisplacements",
                    {"env.action_space=continuous"},
                    "/agent/algorithm: dqn needs env.action_space \"discrete\""},
        BadOverride{"UnknownActionSpace",
                    {"env.action_space=box"},
                    "/env/action_space: unknown value \"box\""},
        BadOverride{"NegativeEvalInterval",
                    {"agent.eval_interval=-1"},
                    "/agent/eval_interval: must be in [0, 1000000]"},
        BadOverride{
            "EarlyStopWithoutCheckpoints",
            {"agent.eval_interval=0", "agent.early_stop_checkpoints=3"},
            "/agent/early_stop_checkpoints: needs checkpoints: set agent.eval_interval > 0"},
        BadOverride{"PpoClipOutOfRange", {"agent.ppo.clip=1.5"}, "/agent/ppo/clip: must be <= 1"},
        BadOverride{
            "PpoUnknownKey", {"agent.ppo.lamda=0.9"}, "/agent/ppo/lamda: unknown key \"lamda\""},
        BadOverride{"PpoAnnealNotABoolean",
                    {"agent.ppo.anneal_learning_rate=1"},
                    "/agent/ppo/anneal_learning_rate: expected a boolean, got a number"},
        BadOverride{"PpoMoreMinibatchesThanSteps",
                    {"agent.ppo.minibatches=300"},
                    "/agent/ppo/minibatches: must not exceed rollout_steps"},
        BadOverride{"SacNegativeAlpha",
                    {"agent.algorithm=sac", "env.action_space=continuous", "agent.sac.alpha=-1"},
                    "/agent/sac/alpha: must not be negative, got -1"},
        BadOverride{"SacZeroBatch", {"agent.sac.batch_size=0"}, "/agent/sac/batch_size: must be"},
        BadOverride{"UeEncoderNotAList",
                    {"agent.algorithm=ppo", "env.observations=[\"ues\"]", "agent.ue_encoder=16"},
                    "/agent/ue_encoder: expected [units, ...] (or [] for none)"},
        BadOverride{
            "UeEncoderZeroWidth",
            {"agent.algorithm=ppo", "env.observations=[\"ues\"]", "agent.ue_encoder=[16, 0]"},
            "/agent/ue_encoder/1: must be >= 1"},
        BadOverride{"UeEncoderTooWide",
                    {"agent.algorithm=ppo", "env.observations=[\"ues\"]", "agent.ue_encoder=[513]"},
                    "/agent/ue_encoder/0: must be <= 512"},
        BadOverride{
            "UeEncoderFractionalWidth",
            {"agent.algorithm=ppo", "env.observations=[\"ues\"]", "agent.ue_encoder=[16.5]"},
            "/agent/ue_encoder/0: expected an integer"},
        BadOverride{"UeEncoderTooDeep",
                    {"agent.algorithm=ppo", "env.observations=[\"ues\"]",
                     "agent.ue_encoder=[8, 8, 8, 8, 8]"},
                    "/agent/ue_encoder: 5 layers; at most 4"},
        BadOverride{"UeEncoderNotPpo",
                    {"env.observations=[\"ues\"]", "agent.ue_encoder=[16]"},
                    "/agent/ue_encoder: only ppo has a UE encoder, not dqn; remove it"},
        BadOverride{"UeEncoderWithoutUes",
                    {"agent.algorithm=ppo", "agent.ue_encoder=[16]"},
                    "/agent/ue_encoder: needs \"ues\" in env.observations"}),
    [](const ::testing::TestParamInfo<BadOverride>& param) { return param.param.name; });

}  // namespace
}  // namespace rlpos
