// A policy folder is self-contained: `position --policy DIR` replays training's own final
// evaluation from what the folder holds, and refuses a scenario that contradicts it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

class PolicyFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() / ("rlpos-policy-" + std::to_string(::getpid()));
    fs::remove_all(out_);
  }
  void TearDown() override { fs::remove_all(out_); }

  // Trains on B (analytic, a few episodes) with `extra` flags; returns result.json.
  nlohmann::json Train(const std::string& extra) {
    const auto r =
        RunCommand(Sim("train --scenario " + kScenarioB + " --fidelity analytic --seed 1 --json " +
                       extra + " --out " + out_.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
  }

  CommandResult Position(const std::string& scenario, const std::string& extra = "") {
    return RunCommand(Sim("position --scenario " + scenario + " --positioner rl --json --policy " +
                          out_.string() + " " + extra));
  }

  fs::path out_;
};

TEST_F(PolicyFolder, AStepTenPolicyReplaysItsTrainingOnPlainB) {
  const auto result = Train("--episodes 30 --set env.step=10");
  ASSERT_TRUE(result.contains("position"));
  // The caller says nothing about env.step: the policy's 10 m moves are flown.
  const auto plain = Position(kScenarioB);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(nlohmann::json::parse(plain.out)["position"], result["position"]);
  // Restated, the same.
  const auto restated = Position(kScenarioB, "--set env.step=10");
  ASSERT_EQ(restated.exit_code, 0) << restated.err;
  EXPECT_EQ(nlohmann::json::parse(restated.out)["position"], result["position"]);
  // Stated otherwise, refused.
  ExpectOneLineRefusal(Position(kScenarioB, "--set env.step=5"), out_.string(),
                       "/env/step: 5.0 in the scenario, 10.0 in the policy");
}

TEST_F(PolicyFolder, AForeignScenarioIsRefused) {
  Train("--episodes 2 --set agent.eval_interval=0 --set env.episode_duration=10");
  // C is B with other demands.
  ExpectOneLineRefusal(Position(kScenarios + "c.json"), out_.string(),
                       "c.json: /ues/0/demand/mcs: 3 in the scenario, 0 in the policy");
  // B's own UEs, one fewer.
  const auto b = nlohmann::json::parse(std::ifstream(kScenarioB));
  nlohmann::json ues = b["ues"];
  ues.erase(ues.size() - 1);
  const std::string fewer = "--set 'ues=" + ues.dump() + "'";
  ExpectOneLineRefusal(Position(kScenarioB, fewer), out_.string(), ": /ues: 3 entries");
  // Evaluation settings are the caller's: another duration, run and fidelity still fit.
  const auto eval = Position(kScenarioB,
                             "--set simulation.duration=3 --set simulation.run=7 "
                             "--set env.fidelity=packet");
  EXPECT_EQ(eval.exit_code, 0) << eval.err;
}

TEST_F(PolicyFolder, TheReplayIsTrainingsOwnEvaluationForEachAlgorithm) {
  for (const std::string algorithm : {"dqn", "ppo"}) {
    SCOPED_TRACE(algorithm);
    fs::remove_all(out_);
    // Hyperparameters and an evaluation the caller's B does not state: the folder holds them.
    const auto result = Train("--algorithm " + algorithm +
                              " --episodes 20 --set agent.hidden=[16] --set agent.eval_episodes=2");
    const auto p = Position(kScenarioB);
    EXPECT_EQ(p.exit_code, 0) << p.err;
    if (p.exit_code == 0) {
      EXPECT_EQ(nlohmann::json::parse(p.out)["position"], result["position"]);
    }
    // The final evaluation is the second of two after 20 training episodes.
    EXPECT_EQ(result.value("eval_run", std::uint64_t{0}),
              result["first_episode_run"].get<std::uint64_t>() + 21);
  }
}

TEST_F(PolicyFolder, FoldersOfEarlierTrainingsStillReplayOrSayWhy) {
  const auto result = Train("--episodes 3 --set agent.hidden=[8]");
  // Written before the seed stream's end was recorded: training's runs give it.
  nlohmann::json old = nlohmann::json::parse(std::ifstream(out_ / "result.json"));
  old.erase("eval_run");
  old.erase("general");
  std::ofstream(out_ / "result.json") << old.dump(2);
  const auto p = Position(kScenarioB);
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_EQ(nlohmann::json::parse(p.out)["position"], result["position"]);
  // Without the scenario it was trained on, a folder cannot be replayed exactly.
  fs::remove(out_ / "scenario.json");
  ExpectOneLineRefusal(Position(kScenarioB), out_.string() + "/scenario.json", "cannot open");
}

}  // namespace
}  // namespace rlpos::testing
