// rlpos-sim train --generated: a policy for any scenario, trained on fresh generated scenarios,
// recorded (what it trained on, the generator seeds), the same twice, and placed in scenarios it
// never saw; bad input is one line and leaves nothing behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/support/command.h"
#include "tests/support/wait_for.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

// A tiny training: 4 envs of 10-step episodes, 2 validation scenarios, a small network.
const std::string kTiny =
    " --generated urban,open --steps 240 --seed 3 --validation-scenarios 2"
    " --set agent.ppo.num_envs=4 --set agent.train_episode_steps=10"
    " --set agent.ppo.rollout_steps=10 --set agent.hidden=[16] --set env.episode_duration=2"
    " --set env.coverage_map=4 --set env.observed_ues=4 --set env.height_map=3";

std::string Bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class Generalist : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rlpos-generalist-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    trained_ = new CommandResult(RunCommand(Sim("train" + kTiny + " --json --out " + Policy())));
  }
  static void TearDownTestSuite() {
    delete trained_;
    fs::remove_all(dir_);
  }
  static std::string Policy() { return (dir_ / "policy").string(); }
  CommandResult Position(const std::string& scenario, const std::string& extra = "") {
    return RunCommand(Sim("position --positioner rl --json --scenario " + scenario + " --policy " +
                          Policy() + extra));
  }

  static fs::path dir_;
  static CommandResult* trained_;
};
fs::path Generalist::dir_;
CommandResult* Generalist::trained_ = nullptr;

TEST_F(Generalist, RecordsWhatItTrainedOnAndPlacesUavsInScenariosItNeverSaw) {
  ASSERT_EQ(trained_->exit_code, 0) << trained_->err;
  const auto result = nlohmann::json::parse(trained_->out);
  EXPECT_EQ(result, nlohmann::json::parse(std::ifstream(Policy() + "/result.json")));
  EXPECT_TRUE(result["general"].get<bool>());
  EXPECT_EQ(result["training"]["generated"], (nlohmann::json{"urban", "open"}));
  EXPECT_EQ(result["training"]["uavs"], (nlohmann::json{1, 1}));
  // 240 steps in rounds of 4 episodes of 10 steps: 6 rounds, 24 episodes, each its own draw
  // from training seed 3's range.
  EXPECT_EQ(result["steps"], 240);
  EXPECT_EQ(result["episodes"], 24);
  EXPECT_EQ(
      result["training"]["generator_seeds"],
      (nlohmann::json{1000000000ULL + 3 * 100000000ULL, 1000000000ULL + 3 * 100000000ULL + 23}));
  EXPECT_EQ(result["training"]["validation_seeds"], (nlohmann::json{500000000, 500000001}));
  // The build: "rlpos <git describe>, ns-3 V, libtorch V, Cyclone DDS V".
  const std::string build = result.value("build", "");
  EXPECT_EQ(build.rfind("rlpos ", 0), 0u) << build;
  EXPECT_NE(build.find(", libtorch "), std::string::npos) << build;
  ASSERT_EQ(result["validation"].size(), 2u);
  for (const auto& v : result["validation"]) {
    EXPECT_GT(v["oracle_reward"].get<double>(), 0.0) << v;
    EXPECT_LE(v["ratio"].get<double>(), 1.0 + 1e-12) << v;
  }
  // The curve: a header and a row per round.
  std::ifstream curve(Policy() + "/learning_curve.csv");
  std::string line;
  int rows = -1;
  while (std::getline(curve, line))
    ++rows;
  EXPECT_EQ(rows, 6);
  // Placed in the shipped scenarios, none of which it trained on.
  for (const char* name : {"a.json", "b.json", "c.json"}) {
    const auto p = Position(kScenarios + name);
    ASSERT_EQ(p.exit_code, 0) << name << ": " << p.err;
    const auto placed = nlohmann::json::parse(p.out);
    EXPECT_EQ(placed["positioner"], "rl");
    EXPECT_GE(placed["reward"].get<double>(), 0.0);
  }
}

TEST_F(Generalist, TheSameCommandTrainsTheSamePolicy) {
  ASSERT_EQ(trained_->exit_code, 0) << trained_->err;
  const std::string again = (dir_ / "again").string();
  const auto r = RunCommand(Sim("train" + kTiny + " --out " + again));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Bytes(again + "/policy.pt"), Bytes(Policy() + "/policy.pt"));
  EXPECT_FALSE(Bytes(again + "/policy.pt").empty());
  // Another seed, another policy.
  const std::string other = (dir_ / "other").string();
  std::string tiny_seed_4 = kTiny;
  tiny_seed_4.replace(tiny_seed_4.find("--seed 3"), 8, "--seed 4");
  ASSERT_EQ(RunCommand(Sim("train" + tiny_seed_4 + " --out " + other)).exit_code, 0);
  EXPECT_NE(Bytes(other + "/policy.pt"), Bytes(Policy() + "/policy.pt"));
}

TEST_F(Generalist, APlacementOutsideWhatItWasTrainedForIsRefused) {
  ASSERT_EQ(trained_->exit_code, 0) << trained_->err;
  // Trained for one UAV; urban3 has three.
  ExpectOneLineRefusal(Position(kScenarios + "urban3.json"), Policy(), "has 3");
  // Its env settings travel with it: a scenario may restate them, not change them.
  ExpectOneLineRefusal(Position(kScenarioB, " --set env.step=10"), Policy(), "/env/step");
  EXPECT_EQ(Position(kScenarioB, " --set env.step=5").exit_code, 0);
}

// Several UAVs as agents: every UAV moves at once on its own observation (agent.joint_steps),
// with a critic that also sees the team's state (agent.ppo.centralised_critic). The folder
// records both, its critic is the wider one, and `position` flies the UAVs at once.
TEST_F(Generalist, SeveralUavsMovingAtOnceWithACentralisedCriticTrainAndPlace) {
  std::string tiny = kTiny;
  tiny.replace(tiny.find("--generated urban,open"), 22, "--generated urban,open --uavs 2-3");
  const auto train = [&](const std::string& name, const std::string& sets) {
    const fs::path out = dir_ / name;
    const auto r = RunCommand(Sim("train" + tiny + sets + " --out " + out.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  };
  const fs::path mappo =
      train("mappo", " --set agent.joint_steps=true --set agent.ppo.centralised_critic=true");
  const fs::path own = train("joint-own-critic", " --set agent.joint_steps=true");
  const auto scenario = nlohmann::json::parse(std::ifstream(mappo / "scenario.json"));
  EXPECT_TRUE(scenario["agent"]["joint_steps"].get<bool>());
  EXPECT_TRUE(scenario["agent"]["ppo"]["centralised_critic"].get<bool>());
  // The same actor's shape; a critic with the team state's inputs besides.
  EXPECT_EQ(Bytes(mappo / "policy.pt").size(), Bytes(own / "policy.pt").size());
  EXPECT_GT(Bytes(mappo / "value.pt").size(), Bytes(own / "value.pt").size());
  const std::string three = (dir_ / "open-3uav.json").string();
  ASSERT_EQ(RunCommand(Sim("generate --seed 95301 --style open --uavs 3 --out " + three)).exit_code,
            0);
  const auto placed = RunCommand(
      Sim("position --positioner rl --json --scenario " + three + " --policy " + mappo.string()));
  ASSERT_EQ(placed.exit_code, 0) << placed.err;
  const auto result = nlohmann::json::parse(placed.out);
  EXPECT_EQ(result["positions"].size(), 3u) << result;
  EXPECT_GE(result["reward"].get<double>(), 0.0);
}

// agent.ue_encoder (the UEs as a set): the folder's scenario.json records it, so `position`
// builds that network; a folder whose scenario.json lost it is refused in one line naming the file.
TEST_F(Generalist, WithTheUeEncoderItPlacesWithTheNetworkItTrained) {
  const fs::path sets = dir_ / "sets";
  const auto r =
      RunCommand(Sim("train" + kTiny + " --set agent.ue_encoder=[8] --out " + sets.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto scenario = nlohmann::json::parse(std::ifstream(sets / "scenario.json"));
  EXPECT_EQ(scenario["agent"]["ue_encoder"], nlohmann::json({8}));
  const auto place = [&](const fs::path& policy) {
    return RunCommand(Sim("position --positioner rl --json --scenario " + kScenarioB +
                          " --policy " + policy.string()));
  };
  const auto placed = place(sets);
  ASSERT_EQ(placed.exit_code, 0) << placed.err;
  EXPECT_GE(nlohmann::json::parse(placed.out)["reward"].get<double>(), 0.0);

  const fs::path stripped = dir_ / "sets-stripped";
  fs::copy(sets, stripped, fs::copy_options::recursive);
  auto without = scenario;
  without["agent"].erase("ue_encoder");
  std::ofstream(stripped / "scenario.json") << without.dump(2);
  const auto refused = place(stripped);
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_NE(refused.err.find((stripped / "policy.pt").string() + ": "), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("agent.ue_encoder"), std::string::npos) << refused.err;
}

// The UEs walk and the policy flies online: asked again every decision interval (the run's own),
// from where the UAV is. Its decision for t = 0 is the placement `position` gives: the same
// flight from the baseline.
TEST_F(Generalist, FliesOnlineInARunWhereTheUesWalk) {
  ASSERT_EQ(trained_->exit_code, 0) << trained_->err;
  const std::string walk = (dir_ / "walk.json").string();
  ASSERT_EQ(
      RunCommand(Sim("generate --seed 4 --style campus --mobility random_waypoint --out " + walk))
          .exit_code,
      0);
  const std::string track = "track --positioner rl --policy " + Policy() + " --scenario " + walk +
                            " --duration 3 --RngRun 2 --json --set env.decision_interval=0.5";
  const auto first = RunCommand(Sim(track));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(RunCommand(Sim(track)).out, first.out);  // seeded: the same bytes
  const auto run = nlohmann::json::parse(first.out);
  EXPECT_EQ(run["positioner"], "rl");
  EXPECT_EQ(run["policy"], Policy());
  EXPECT_EQ(run["intervals"], 6);
  const auto placed = Position(walk);
  ASSERT_EQ(placed.exit_code, 0) << placed.err;
  EXPECT_EQ(run["series"][0]["positions"][0], nlohmann::json::parse(placed.out)["position"]);
  for (const auto& interval : run["series"]) {
    EXPECT_GE(interval["reward"].get<double>(), 0.0) << interval;
    EXPECT_LE(interval["reward"].get<double>(), 1.0) << interval;
  }
  // Refused in one line: no policy, a policy for another positioner, a per-scenario policy.
  const std::string base = "track --scenario " + walk + " --duration 1 --RngRun 1 ";
  const auto bare = RunCommand(Sim(base + "--positioner rl"));
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("--policy: is required for the rl positioner"), std::string::npos)
      << bare.err;
  const auto other = RunCommand(Sim(base + "--positioner oracle --policy " + Policy()));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("only the rl positioner flies a policy"), std::string::npos)
      << other.err;
  const fs::path one = dir_ / "one-scenario";
  fs::create_directories(one);
  for (const char* file : {"policy.pt", "scenario.json"})
    fs::copy_file(fs::path(Policy()) / file, one / file, fs::copy_options::overwrite_existing);
  auto result = nlohmann::json::parse(std::ifstream(Policy() + "/result.json"));
  result["general"] = false;
  std::ofstream(one / "result.json") << result.dump();
  ExpectOneLineRefusal(RunCommand(Sim(base + "--positioner rl --policy " + one.string())),
                       one.string(), "is not a policy for any scenario");
}

// Killed once its first checkpoint is written, the same command goes on from it and ends with
// the uninterrupted run's policy, curve and result.
TEST_F(Generalist, KilledAndRunAgainItResumesToTheSamePolicy) {
  std::string longer = kTiny + " --checkpoint-every 0";
  longer.replace(longer.find("--steps 240"), 11, "--steps 12000");
  const std::string whole = (dir_ / "whole").string();
  const std::string resumed = (dir_ / "resumed").string();
  ASSERT_EQ(RunCommand(Sim("train" + longer + " --out " + whole)).exit_code, 0);

  const std::string command = Sim("train" + longer + " --out " + resumed);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::execl("/bin/sh", "sh", "-c", ("exec " + command + " 2>/dev/null").c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const fs::path progress = resumed + ".partial/checkpoint/progress.json";
  const bool checkpointed = WaitFor([&] { return fs::exists(progress); }, 120.0);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(checkpointed) << "no checkpoint within 120 s";
  ASSERT_FALSE(fs::exists(resumed)) << "it ended before it was killed: give it more steps";

  const auto again = RunCommand(Sim("train" + longer + " --out " + resumed));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("resuming from the checkpoint in " + resumed + ".partial"),
            std::string::npos)
      << again.err;
  EXPECT_EQ(Bytes(resumed + "/policy.pt"), Bytes(whole + "/policy.pt"));
  EXPECT_EQ(Bytes(resumed + "/learning_curve.csv"), Bytes(whole + "/learning_curve.csv"));
  auto result = nlohmann::json::parse(std::ifstream(resumed + "/result.json"));
  auto expected = nlohmann::json::parse(std::ifstream(whole + "/result.json"));
  result.erase("train_seconds");
  expected.erase("train_seconds");
  EXPECT_EQ(result, expected);
  EXPECT_FALSE(fs::exists(resumed + "/checkpoint"));
  EXPECT_FALSE(fs::exists(resumed + ".partial"));

  // Another budget is another training: its checkpoint is not taken for this one's.
  fs::remove_all(resumed);
  fs::create_directories(resumed + ".partial/checkpoint");
  std::ofstream(progress) << R"({"fingerprint": "another"})";
  const auto other = RunCommand(Sim("train" + longer + " --out " + resumed));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("holds the checkpoint of another training"), std::string::npos)
      << other.err;
}

// --scenarios DIR: the same training over a user's own set, recorded by file name.
TEST_F(Generalist, TrainsOnAUsersOwnSet) {
  const fs::path set = dir_ / "set";
  fs::create_directories(set);
  fs::copy_file(kScenarios + "a.json", set / "a.json");
  fs::copy_file(kScenarioB, set / "b.json");
  std::string args = kTiny;
  args.replace(args.find("--generated urban,open"), 22, "--scenarios " + set.string());
  const std::string out = (dir_ / "on-set").string();
  const auto r = RunCommand(Sim("train" + args + " --json --out " + out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  EXPECT_TRUE(result["general"].get<bool>());
  EXPECT_EQ(result["training"]["scenarios"], (nlohmann::json{"a.json", "b.json"}));
  EXPECT_EQ(result["training"]["uavs"], (nlohmann::json{1, 1}));
  EXPECT_FALSE(result["training"].contains("generator_seeds"));
  const auto p = RunCommand(
      Sim("position --positioner rl --scenario " + kScenarios + "c.json --policy " + out));
  EXPECT_EQ(p.exit_code, 0) << p.err;
}

// The policies shipped in policies/ still load with this build and place UAVs: a one-UAV policy
// in B, where the oracle's reward is 1 (every UE in LoS, every demand carried); a policy for
// several UAVs in a generated suburb of three (seed 7, outside the training and held-out seeds),
// where the UAVs start at 0.24 (the baseline) and coordinate descent reaches 0.995.
TEST(ShippedPolicies, EachPlacesItsUavsInAScenarioItNeverSaw) {
  const fs::path dir = fs::temp_directory_path() / ("rlpos-shipped-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string suburb3 = (dir / "suburb3.json").string();
  ASSERT_EQ(RunCommand(Sim("generate --seed 7 --style suburb --uavs 3 --out " + suburb3)).exit_code,
            0);
  int shipped = 0;
  for (const auto& entry : fs::directory_iterator(std::string(RLPOS_SOURCE_DIR) + "/policies")) {
    if (!entry.is_directory())
      continue;
    ++shipped;
    std::ifstream in(entry.path() / "result.json");
    const auto trained = nlohmann::json::parse(in)["training"]["uavs"];
    const bool several = trained.at(1).get<int>() > 1;
    const auto r =
        RunCommand(Sim("position --positioner rl --json --scenario " +
                       (several ? suburb3 : kScenarioB) + " --policy " + entry.path().string()));
    ASSERT_EQ(r.exit_code, 0) << entry.path() << ": " << r.err;
    EXPECT_GE(nlohmann::json::parse(r.out)["reward"].get<double>(), several ? 0.9 : 0.95)
        << entry.path();
  }
  fs::remove_all(dir);
  EXPECT_GE(shipped, 1);
}

struct BadTrain {
  std::string name;  // the test's
  std::string args;
  std::string names;  // what the one line must name
};

class GeneralistBadInput : public ::testing::TestWithParam<BadTrain> {};

std::string NameOf(const ::testing::TestParamInfo<BadTrain>& p) {
  return p.param.name;
}

TEST_P(GeneralistBadInput, IsOneLineAnExitOf2AndNothingWritten) {
  const fs::path out =
      fs::temp_directory_path() / ("rlpos-generalist-bad-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto r = RunCommand(Sim("train " + GetParam().args + " --out " + out.string()));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rlpos-sim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().names), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

INSTANTIATE_TEST_SUITE_P(
    Refusals, GeneralistBadInput,
    ::testing::Values(
        BadTrain{"UnknownStyle", "--generated mars --steps 100",
                 "--generated: unknown style \"mars\""},
        BadTrain{"NoSteps", "--generated urban", "--steps: is required"},
        BadTrain{"ScenarioToo", "--generated urban --steps 100 --scenario " + kScenarioB,
                 "--scenario"},
        BadTrain{"UavsFromZero", "--generated urban --steps 100 --uavs 0-2", "--uavs"},
        BadTrain{"UavsDescending", "--generated urban --steps 100 --uavs 2-1", "--uavs"},
        BadTrain{"TooManyUes", "--generated urban --steps 100 --ues 500", "--ues"},
        BadTrain{"Episodes", "--generated urban --steps 100 --episodes 5", "--episodes"},
        BadTrain{"Dqn", "--generated urban --steps 100 --algorithm dqn", "--algorithm"},
        BadTrain{"PacketFidelity", "--generated urban --steps 100 --fidelity packet", "--fidelity"},
        BadTrain{"OwnObservation",
                 "--generated urban --steps 100 --set env.observations=[\\\"x\\\",\\\"zone\\\"]",
                 "\"x\" is one scenario's own"},
        BadTrain{"BadSetting", "--generated urban --steps 100 --set agent.ppo.gamma=7",
                 "--set agent.ppo.gamma=7"},
        BadTrain{"MissingFolder", "--scenarios /nonexistent/rlpos --steps 100", "--scenarios"},
        BadTrain{"BadScenarioInTheSet",
                 "--scenarios " + std::string(RLPOS_SOURCE_DIR) + "/tests/e2e/campaigns" +
                     " --steps 100",
                 "--scenarios: " + std::string(RLPOS_SOURCE_DIR) + "/tests/e2e/campaigns/"},
        BadTrain{"UavsWithASet", "--scenarios " + kScenarios + " --uavs 2 --steps 100", "--uavs"},
        BadTrain{"BothSources", "--generated urban --scenarios " + kScenarios + " --steps 100",
                 "exclude"},
        BadTrain{"NoSource", "", "--scenario: is required"},
        BadTrain{"SeedBeyondTheDrawRanges", "--generated urban --steps 100 --seed 2000000",
                 "--seed: at most 1000000"},
        BadTrain{"StepsForOneScenario", "--scenario " + kScenarioB + " --steps 100", "--steps"}),
    NameOf);

}  // namespace
}  // namespace rlpos::testing
