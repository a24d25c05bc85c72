// rlpos-sim as a user runs it: exit codes, one-line errors naming file and JSON path, nothing on
// stdout on failure, deterministic results per RngRun.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/support/command.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

// Writes `text` to a fresh file and returns its path.
std::string TempFile(const std::string& text) {
  char path[] = "/tmp/rlpos-test-scenario-XXXXXX";
  const int fd = mkstemp(path);
  close(fd);
  std::ofstream(path) << text;
  return path;
}

void ExpectOneLineError(const CommandResult& r, int exit_code, const std::string& fragment) {
  EXPECT_EQ(r.exit_code, exit_code) << r.err;
  EXPECT_TRUE(r.out.empty()) << "stdout must stay empty on failure: " << r.out;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(r.err.find("rlpos-sim: error: "), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

// rlpos-sim run with `arguments`: a usage error (exit 2) of one line holding `fragment`.
void ExpectUsageError(const std::string& arguments, const std::string& fragment) {
  ExpectOneLineError(RunCommand(Sim(arguments)), 2, fragment);
}

TEST(RlposSimCli, ValidatePrintsASummary) {
  const auto r = RunCommand(Sim("validate " + kScenarioB));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // In LoS, said as such: "nLoS 1/4" read as one UE out of sight.
  EXPECT_NE(r.out.find("baseline    (50, 50, 25): in LoS 1/4"), std::string::npos) << r.out;
}

TEST(RlposSimCli, ValidateSaysHowTheUesMove) {
  EXPECT_NE(RunCommand(Sim("validate " + kScenarioB)).out.find("  mobility    4 UEs: static\n"),
            std::string::npos);
  const auto r = RunCommand(Sim(
      "validate " + kScenarioB +
      " --set 'ues.2.mobility={\"model\": \"random_waypoint\", \"speed\": [1, 2], \"pause\": 0}'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  mobility    3 UEs (ue0, ue1, ue3): static\n"
                       "  mobility    1 UE (ue2): random_waypoint at 1-2 m/s, pause 0 s\n"),
            std::string::npos)
      << r.out;
}

TEST(RlposSimCli, BadMobilityIsAOneLineErrorWithItsPath) {
  ExpectUsageError(
      "validate " + kScenarioB +
          " --set 'ues.2.mobility={\"model\": \"crowd\", \"target\": [50, 50]}'",
      "/ues/2/mobility/target: crowd target (50, 50) is inside building 0 (\"tower\")");
  ExpectUsageError("validate " + kScenarioB +
                       " --set 'ues.2.mobility={\"model\": \"gauss_markov\", \"alpha\": 2}'",
                   "/ues/2/mobility/alpha: must be <= 1, got 2");
}

TEST(RlposSimCli, ValidateCountsTheUesInLoSOfSeveralUavs) {
  const auto r = RunCommand(
      Sim("validate " + std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  baseline    in LoS "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nLoS"), std::string::npos) << r.out;
}

TEST(RlposSimCli, MissingFile) {
  ExpectUsageError("validate /nonexistent.json",
                   "/nonexistent.json: cannot open: No such file or directory");
}

TEST(RlposSimCli, MalformedJson) {
  const std::string file = TempFile("{\"ues\": [}");
  ExpectUsageError("validate " + file, file + ": /: malformed JSON at line 1");
}

TEST(RlposSimCli, UnknownKeyWithSuggestion) {
  ExpectUsageError("validate " + kScenarioB + " --set wifi.chanel=36",
                   "/wifi/chanel: unknown key \"chanel\"; did you mean \"channel\"?");
}

TEST(RlposSimCli, UnknownTypeId) {
  ExpectUsageError(
      "validate " + kScenarioB + " --set propagation.type=ns3::FriisPropagationLosModel",
      "/propagation/type: unknown ns-3 TypeId \"ns3::FriisPropagationLosModel\"; did you mean "
      "\"ns3::FriisPropagationLossModel\"?");
}

TEST(RlposSimCli, TypeOfTheWrongKind) {
  ExpectUsageError("validate " + kScenarioB + " --set wifi.rate_manager.type=ns3::Node",
                   "/wifi/rate_manager/type: \"ns3::Node\" is not a ns3::WifiRemoteStationManager");
}

TEST(RlposSimCli, AttributeTheTypeDoesNotHave) {
  ExpectUsageError(
      "validate " + kScenarioB + " --set propagation.attributes.LosModel.attributes.Frequncy=5e9",
      "/propagation/attributes/LosModel/attributes/Frequncy: "
      "ns3::ItuR1411LosPropagationLossModel has no attribute \"Frequncy\"; did you mean "
      "\"Frequency\"?");
}

TEST(RlposSimCli, AttributeValueOfTheWrongType) {
  ExpectUsageError(
      "validate " + kScenarioB +
          " --set 'propagation.attributes.NlosModel.attributes.Environment=\"Moon\"'",
      "/propagation/attributes/NlosModel/attributes/Environment: invalid value \"Moon\"");
}

TEST(RlposSimCli, ChannelNotOfThatWidth) {
  ExpectUsageError("validate " + kScenarioB + " --set wifi.channel=36",
                   "/wifi/channel: channel 36 is not a 160 MHz 802.11ac channel");
}

TEST(RlposSimCli, BadPositions) {
  ExpectUsageError("eval --scenario " + kScenarioB + " --position 1,2",
                   "--position: expected x,y,z");
  ExpectUsageError("eval --scenario " + kScenarioB + " --position 50,50,10",
                   "--position: (50, 50, 10) is inside building 0 (\"tower\")");
  ExpectUsageError("eval --scenario " + kScenarioB + " --position 50,150,10",
                   "--position: (50, 150, 10) is outside the venue");
}

TEST(RlposSimCli, ASetErrorNamesTheOverrideNotTheFile) {
  const auto r = RunCommand(Sim("validate " + kScenarioB + " --set wifi.width=77"));
  ExpectOneLineError(r, 2, "rlpos-sim: error: --set wifi.width=77: /wifi/width: must be");
  EXPECT_EQ(r.err.find("b.json"), std::string::npos) << r.err;
  // An error in the file, beside an override elsewhere, still names the file.
  nlohmann::json document = nlohmann::json::parse(std::ifstream(kScenarioB));
  document["wifi"]["width"] = 77;
  const std::string file = TempFile(document.dump());
  const auto file_error = RunCommand(Sim("validate " + file + " --set wifi.mode=adhoc"));
  ExpectOneLineError(file_error, 2, file + ": /wifi/width: must be");
  EXPECT_EQ(file_error.err.find("--set"), std::string::npos) << file_error.err;
}

TEST(RlposSimCli, CommandLineErrorsAreOneLine) {
  // CLI11's own errors keep the project's format: one line, the program's prefix, exit 2.
  ExpectUsageError("position --scenario " + kScenarioB + " --positioner kmean",
                   "--positioner: kmean not in");
  ExpectUsageError("validate " + kScenarioB + " --no-such-flag", "--no-such-flag");
  ExpectUsageError("eval --scenario " + kScenarioB, "--position");
  ExpectUsageError("", "subcommand");
}

TEST(RlposSimCli, UsageErrorsExitTwo) {
  EXPECT_EQ(RunCommand(Sim("")).exit_code, 2);
  EXPECT_EQ(RunCommand(Sim("eval --scenario " + kScenarioB)).exit_code, 2);  // no --position
  EXPECT_EQ(RunCommand(Sim("eval --scenario " + kScenarioB + " --position 1,1,1 --duration -3"))
                .exit_code,
            2);
}

TEST(RlposSimCli, Ns3AbortIsACleanFailure) {
  // ARF cannot drive 802.11ac (no HT rates): ns-3 aborts when the devices initialise.
  const auto r = RunCommand(Sim("eval --scenario " + kScenarioB +
                                " --position 50,35,10 --duration 1.5 --no-progress"
                                " --set wifi.rate_manager.type=ns3::ArfWifiManager"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("rlpos-sim: error: ns-3 aborted the simulation"), std::string::npos)
      << r.err;
}

nlohmann::json EvalJson(const std::string& extra) {
  const auto r = RunCommand(Sim("eval --scenario " + kScenarioB +
                                " --position 50,50,25 --duration 2 --json --no-progress " + extra));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(RlposSimCli, SameRunSameMetricsOtherRunCloseButDifferent) {
  const auto run1 = EvalJson("--run 1");
  const auto again = EvalJson("--RngRun 1");
  const auto run2 = EvalJson("--run 2");
  EXPECT_EQ(run1, again);
  EXPECT_NE(run1["mean_delay_ms"], run2["mean_delay_ms"]);
  const double t1 = run1["aggregate_throughput_mbps"];
  const double t2 = run2["aggregate_throughput_mbps"];
  EXPECT_NEAR(t2, t1, 0.1 * t1);
  std::printf("RngRun 1: %.3f Mbit/s %.3f ms; RngRun 2: %.3f Mbit/s %.3f ms\n", t1,
              run1["mean_delay_ms"].get<double>(), t2, run2["mean_delay_ms"].get<double>());
}

// An eval records the reward the oracle and the agent score its placement with: the analytic
// model's, whatever the RngRun.
TEST(RlposSimCli, AnEvalsRewardIsThePositionersAnalyticReward) {
  const auto baseline =
      RunCommand(Sim("position --scenario " + kScenarioB + " --positioner baseline --json"));
  ASSERT_EQ(baseline.exit_code, 0) << baseline.err;
  const double expected = nlohmann::json::parse(baseline.out).at("reward");
  const auto run1 = EvalJson("--run 1");
  const auto run2 = EvalJson("--run 2");
  EXPECT_DOUBLE_EQ(run1.at("reward").get<double>(), expected) << run1;
  EXPECT_DOUBLE_EQ(run2.at("reward").get<double>(), expected) << run2;
}

// The README's third quick-start command, shorter: ad hoc, RTS/CTS and ns-3's HybridBuildings
// loss model, which reads ns-3's building list. Packet level runs it; the analytic model, whose
// reward an eval records, refuses it: the eval succeeds with a null reward and says why, in one
// line after the packets' figures.
TEST(RlposSimCli, AnEvalTheAnalyticModelCannotScoreHasANullReward) {
  const auto r =
      RunCommand(Sim("eval --scenario " + kScenarioB +
                     " --position 50,35,10 --set wifi.mode=adhoc --set wifi.rts_cts=true"
                     " --set 'propagation={\"type\": \"ns3::HybridBuildingsPropagationLossModel\"}'"
                     " --duration 1.5 --json --no-progress"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(r.out);
  EXPECT_TRUE(m.at("reward").is_null()) << m;
  EXPECT_GT(m.at("aggregate_throughput_mbps").get<double>(), 0.0) << m;
  EXPECT_EQ(r.err,
            "[warning] reward: null, the analytic model refuses this scenario: /propagation: "
            "ns3::HybridBuildingsPropagationLossModel reads ns-3's process-wide building list, "
            "which the analytic fidelity does not build\n");
}

// An eval whose settings cannot run fails before it simulates: one line, no progress shown.
TEST(RlposSimCli, AnEvalOfBadSettingsFailsBeforeSimulating) {
  ExpectUsageError("eval --scenario " + kScenarioB + " --position 50,35,10" +
                       " --set 'propagation={\"type\": \"ns3::NoSuchPropagationLossModel\"}'",
                   "/propagation/type");
  ExpectUsageError("eval --scenario " + kScenarioB + " --position 50,35,10 --set wifi.mode=mesh",
                   "/wifi/mode");
}

TEST(RlposSimCli, OracleCandidatesNotRescoredCarryNull) {
  const auto r =
      RunCommand(Sim("position --scenario " + kScenarioB + " --positioner oracle --json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  const auto& candidates = out.at("candidates");
  ASSERT_EQ(candidates.size(), 5u) << r.out;
  // The best three analytic positions are re-scored at packet level, the others are not.
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& reward = candidates[i].at("packet_reward");
    if (i < 3) {
      EXPECT_TRUE(reward.is_number()) << i << ": " << reward;
    } else {
      EXPECT_TRUE(reward.is_null()) << i << ": " << reward;
    }
  }
}

const std::string kUrban3 = std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/urban3.json";

// The three-UAV scenario at packet level, briefly: one --position per UAV, per-UAV metrics.
TEST(RlposSimCli, EvalOfThreeUavs) {
  const auto r = RunCommand(Sim("eval --scenario " + kUrban3 +
                                " --position 135,85,60 --position 20,135,60 --position 70,15,60"
                                " --duration 1.5 --run 2 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(r.out);
  ASSERT_EQ(m["uavs"].size(), 3u);
  int served = 0;
  double throughput = 0;
  for (const auto& uav : m["uavs"]) {
    served += uav["ues_served"].get<int>();
    throughput += uav["throughput_mbps"].get<double>();
    EXPECT_GT(uav["throughput_mbps"].get<double>(), 0.0) << uav;
  }
  EXPECT_EQ(served, 20);
  EXPECT_NEAR(throughput, m["aggregate_throughput_mbps"].get<double>(), 1e-6);
  EXPECT_EQ(m["uavs"][1]["name"], "uav2");
  EXPECT_EQ(m["uavs"][2]["channel"], 106);
  EXPECT_EQ(m["ues"][0]["uav"].get<std::string>().rfind("uav", 0), 0u);
}

TEST(RlposSimCli, EvalNeedsAPositionPerUav) {
  ExpectUsageError("eval --scenario " + kUrban3 + " --position 135,85,60",
                   "--position: scenario urban3 has 3 UAV(s): give one x,y,z each (1 given)");
  ExpectUsageError("eval --scenario " + kUrban3 +
                       " --position 135,85,60 --position 135,85.5,60 --position 70,15,60",
                   "--position #2: UAVs uav1 and uav2 overlap");
  ExpectUsageError("eval --scenario " + kUrban3 +
                       " --position 135,85,60 --position 25,25,10 --position 70,15,60",
                   "--position #2: (25, 25, 10) is inside building 0");
}

TEST(RlposSimCli, DescribeHyperparametersOfOneAlgorithm) {
  const auto r = RunCommand(Sim("describe hyperparameters --algorithm ppo"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## agent\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("## ppo\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| `agent.ppo.anneal_learning_rate` | boolean | true |"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("## sac"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("## dqn"), std::string::npos) << r.out;
  // The shared keys with PPO's own defaults, not DQN's 1000 episodes.
  EXPECT_NE(r.out.find("| `agent.train_episodes` | integer | 4000 |"), std::string::npos) << r.out;
}

TEST(RlposSimCli, DescribeHyperparametersOfEveryAlgorithmIsTheDocsPage) {
  const auto r = RunCommand(Sim("describe hyperparameters"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(std::string(RLPOS_SOURCE_DIR) + "/docs/hyperparameters.md");
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(r.out, page);
}

TEST(RlposSimCli, DescribeRefusesAnUnknownAlgorithmOrNoTable) {
  const auto unknown = RunCommand(Sim("describe hyperparameters --algorithm a2c"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(unknown.out.empty()) << unknown.out;
  EXPECT_NE(unknown.err.find("--algorithm"), std::string::npos) << unknown.err;
  EXPECT_EQ(RunCommand(Sim("describe")).exit_code, 2);
}

TEST(RlposSimCli, DescribeSettingsEverySectionOrOne) {
  const auto all = RunCommand(Sim("describe settings"));
  ASSERT_EQ(all.exit_code, 0) << all.err;
  for (const char* heading :
       {"## venue\n", "## wifi\n", "## env.reward\n", "## agent\n", "## sac\n"})
    EXPECT_NE(all.out.find(heading), std::string::npos) << heading;
  const auto wifi = RunCommand(Sim("describe settings --section wifi"));
  ASSERT_EQ(wifi.exit_code, 0) << wifi.err;
  EXPECT_EQ(wifi.out.rfind("| key | type | default | values | |\n", 0), 0u) << wifi.out;
  EXPECT_NE(wifi.out.find("| `wifi.tx_power` | real | 20.0 dBm | [-30, 40] dBm |"),
            std::string::npos)
      << wifi.out;
  EXPECT_EQ(wifi.out.find("env."), std::string::npos) << wifi.out;
  const auto json = RunCommand(Sim("describe settings --section env.reward --json"));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto sections = nlohmann::json::parse(json.out);
  ASSERT_EQ(sections.size(), 1u) << json.out;
  EXPECT_EQ(sections[0]["settings"][0]["key"], "env.reward.name");
  const auto unknown = RunCommand(Sim("describe settings --section wlan"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(unknown.out.empty()) << unknown.out;
  EXPECT_NE(unknown.err.find("--section"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace rlpos::testing
