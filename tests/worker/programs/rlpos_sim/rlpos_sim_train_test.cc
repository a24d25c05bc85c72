// rlpos-sim train and position as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "tests/support/command.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

class TrainCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() / ("rlpos-train-" + std::to_string(::getpid()));
    fs::remove_all(out_);
  }
  void TearDown() override { fs::remove_all(out_); }
  fs::path out_;
};

TEST_F(TrainCommand, WritesPolicyCurveAndResultThenRlReplaysIt) {
  const auto r =
      RunCommand(Sim("train --scenario " + kScenarioB +
                     " --fidelity analytic --seed 4 --episodes 2 --set agent.eval_interval=0"
                     " --set agent.train_episode_steps=100 --json --out " +
                     out_.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  EXPECT_EQ(result["fidelity"], "analytic");
  EXPECT_EQ(result["seed"], 4);
  EXPECT_TRUE(fs::exists(out_ / "policy.pt"));
  EXPECT_TRUE(fs::exists(out_ / "scenario.json"));
  std::ifstream curve(out_ / "learning_curve.csv");
  std::string line;
  std::getline(curve, line);
  EXPECT_EQ(line,
            "episode,phase,steps,total_reward,mean_reward,epsilon,updates,mean_loss,final_reward,"
            "x,y,z,n_los,throughput_mbps");
  std::vector<std::vector<std::string>> episodes;
  while (std::getline(curve, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    episodes.push_back(cells);
  }
  ASSERT_EQ(episodes.size(), 3u);  // 2 training episodes + 1 evaluation
  // Training episodes learn (updates, a positive loss); the greedy evaluation does not.
  EXPECT_EQ(episodes[1][1], "train");
  EXPECT_GT(std::stoi(episodes[1][6]), 0);
  EXPECT_GT(std::stod(episodes[1][7]), 0.0);
  EXPECT_EQ(episodes[2][1], "eval");
  EXPECT_EQ(episodes[2][6], "0");
  int rows = 0;
  // The evaluation episode's flight, one row per step; it ends at the result's position.
  std::ifstream trajectory(out_ / "trajectory.csv");
  std::getline(trajectory, line);
  EXPECT_EQ(line, "episode,step,uav,action,x,y,z,n_los,throughput_mbps,reward");
  std::string last;
  rows = 0;
  while (std::getline(trajectory, line))
    ++rows, last = line;
  EXPECT_EQ(rows, 1000);  // 100 s of 0.1 s decisions
  const auto& p_end = result["position"];
  const std::string end = "3,1000,";
  EXPECT_EQ(last.rfind(end, 0), 0u) << last;
  std::ostringstream xyz;
  xyz << "," << p_end[0].get<double>() << "," << p_end[1].get<double>() << ","
      << p_end[2].get<double>() << ",";
  EXPECT_NE(last.find(xyz.str()), std::string::npos) << last << " vs " << xyz.str();
  EXPECT_NE(r.err.find("episode 3/3 (eval)"), std::string::npos) << r.err;

  const auto p = RunCommand(Sim("position --scenario " + kScenarioB +
                                " --positioner rl --json --policy " + out_.string()));
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_EQ(nlohmann::json::parse(p.out)["position"], result["position"]);

  // An existing output folder is refused, and left as it was.
  const auto again = RunCommand(Sim("train --scenario " + kScenarioB +
                                    " --fidelity analytic --episodes 1 --out " + out_.string()));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--out: " + out_.string() + " already exists"), std::string::npos)
      << again.err;
  EXPECT_TRUE(fs::exists(out_ / "policy.pt"));
}

TEST_F(TrainCommand, CheckpointsKeepTheBestPolicyWhichIsTheOneSavedAndReplayed) {
  const auto r = RunCommand(Sim("train --scenario " + kScenarioB +
                                " --fidelity analytic --algorithm ppo --seed 2 --episodes 3"
                                " --set agent.eval_interval=1 --json --out " +
                                out_.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  std::ifstream curve(out_ / "learning_curve.csv");
  std::string line;
  std::getline(curve, line);
  std::vector<std::string> phases;
  std::vector<double> checkpoint_rewards;
  while (std::getline(curve, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    phases.push_back(cells[0] + cells[1]);
    if (cells[1] == "checkpoint")
      checkpoint_rewards.push_back(std::stod(cells[8]));
  }
  EXPECT_EQ(phases, (std::vector<std::string>{"1train", "1checkpoint", "2train", "2checkpoint",
                                              "3train", "3checkpoint", "4eval"}));
  ASSERT_EQ(checkpoint_rewards.size(), 3u);
  // The evaluation flies the best checkpoint's policy (the latest of equals) to its reward.
  const int best = static_cast<int>(
      std::max_element(checkpoint_rewards.rbegin(), checkpoint_rewards.rend()).base() -
      checkpoint_rewards.begin());
  EXPECT_EQ(result["policy_episode"], best);
  EXPECT_EQ(result["eval_interval"], 1);
  EXPECT_NEAR(result["reward"].get<double>(), checkpoint_rewards[best - 1], 1e-4);
  // The saved policy is the kept one: the rl positioner lands where the evaluation did.
  const auto p = RunCommand(Sim("position --scenario " + kScenarioB +
                                " --positioner rl --json --policy " + out_.string()));
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_EQ(nlohmann::json::parse(p.out)["position"], result["position"]);
}

// train's stdout is its result alone; its progress on stderr is a line for the first and every
// 20th part of the training episodes and for each evaluation (the learning curve has every
// episode), naming each algorithm's own figures: DQN's epsilon, PPO's entropy and learning
// rate, SAC's alpha.
TEST_F(TrainCommand, StdoutIsTheResultAndProgressAFewLinesOfTheAlgorithmsOwnFigures) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> own = {
      {"dqn", {", epsilon 0."}},
      {"ppo", {", entropy ", ", learning rate "}},
      {"sac", {", alpha "}}};
  for (const auto& [algorithm, figures] : own) {
    const fs::path out = out_ / algorithm;
    const auto r =
        RunCommand(Sim("train --scenario " + kScenarioB +
                       " --fidelity analytic --seed 1 --episodes 100 --algorithm " + algorithm +
                       " --set agent.train_episode_steps=10 --set agent.eval_interval=0"
                       " --out " +
                       out.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << r.out;
    EXPECT_EQ(r.out.rfind("trained B (" + algorithm + ", analytic, seed 1): final position", 0), 0u)
        << r.out;
    // Episodes 1, 5, 10, ..., 100 and the evaluation: 22 lines (a few more only if 30 s passed
    // between two of them).
    const auto lines = std::count(r.err.begin(), r.err.end(), '\n');
    EXPECT_GE(lines, 22) << r.err;
    EXPECT_LE(lines, 25) << r.err;
    EXPECT_EQ(r.err.rfind("episode 1/101 (train): 10 steps, reward ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("\nepisode 5/101 (train)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("\nepisode 6/101 (train)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\nepisode 100/101 (train)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\nepisode 101/101 (eval): 1000 steps"), std::string::npos) << r.err;
    for (const std::string& figure : figures)
      EXPECT_NE(r.err.find(figure), std::string::npos) << algorithm << ": " << figure << "\n"
                                                       << r.err;
    if (algorithm != "dqn") {
      EXPECT_EQ(r.err.find("epsilon"), std::string::npos) << algorithm << ": " << r.err;
    }
  }
}

TEST_F(TrainCommand, TheProgressLineOfSeveralUavsShowsEachOne) {
  const std::string campus2 = std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/campus2.json";
  const auto r = RunCommand(Sim("train --scenario " + campus2 +
                                " --fidelity analytic --episodes 1 --set env.episode_duration=2"
                                " --set agent.eval_interval=0 --json --out " +
                                out_.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto positions = nlohmann::json::parse(r.out)["positions"];
  ASSERT_EQ(positions.size(), 2u);
  std::ostringstream both;
  both << "final";
  for (const auto& p : positions) {
    char text[96];
    std::snprintf(text, sizeof text, " (%.1f, %.1f, %.1f)", p[0].get<double>(), p[1].get<double>(),
                  p[2].get<double>());
    both << text;
  }
  const std::size_t eval = r.err.find("episode 2/2 (eval)");
  ASSERT_NE(eval, std::string::npos) << r.err;
  EXPECT_NE(r.err.find(both.str() + " in LoS", eval), std::string::npos) << r.err;
}

// agent.joint_steps: every UAV moves in each step (a trajectory row per UAV and step), in
// training, in the evaluation and in the replay, which lands where the training's evaluation
// did; also with PPO's centralised critic (its wider value.pt loads with the policy). Without it
// the UAVs take turns: one row per step.
TEST_F(TrainCommand, JointStepsMoveEveryUavInEachStepAndReplay) {
  const std::string urban3 = kScenarios + "urban3.json";
  for (const bool joint : {true, false}) {
    const std::string sets = " --set agent.joint_steps=" + std::string(joint ? "true" : "false") +
                             " --set agent.train_episodes=30 --set env.episode_duration=2";
    const fs::path out = out_ / (joint ? "joint" : "turns");
    for (const std::string algorithm : {"ppo", "ppo+critic", "dqn"}) {
      const bool critic = algorithm == "ppo+critic";
      fs::remove_all(out);
      const auto r =
          RunCommand(Sim("train --scenario " + urban3 + " --fidelity analytic" + " --algorithm " +
                         (critic ? "ppo --set agent.ppo.centralised_critic=true" : algorithm) +
                         sets + " --json --out " + out.string()));
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const auto trained = nlohmann::json::parse(r.out)["positions"];
      std::ifstream trajectory(out / "trajectory.csv");
      std::string line;
      std::getline(trajectory, line);  // the header
      std::vector<int> rows_per_step(21, 0);
      std::vector<int> moved_per_step(21, 0);  // joint: the UAVs whose displacement is not 0
      while (std::getline(trajectory, line)) {
        std::vector<std::string> cells;
        std::stringstream split(line);
        for (std::string cell; std::getline(split, cell, ',');)
          cells.push_back(cell);
        const auto step = static_cast<std::size_t>(std::stoi(cells.at(1)));
        ++rows_per_step.at(step);
        moved_per_step.at(step) += cells.at(3) != "0 0 0";
      }
      int steps_moving_several = 0;
      for (std::size_t step = 1; step <= 20; ++step) {
        EXPECT_EQ(rows_per_step[step], joint ? 3 : 1) << algorithm << " step " << step;
        steps_moving_several += moved_per_step[step] > 1;
      }
      if (joint) {
        EXPECT_GT(steps_moving_several, 0) << algorithm << ": no step moved several UAVs";
      }
      const auto replay =
          RunCommand(Sim("position --scenario " + urban3 + " --positioner rl --json --policy " +
                         out.string() + sets));
      ASSERT_EQ(replay.exit_code, 0) << replay.err;
      EXPECT_EQ(nlohmann::json::parse(replay.out)["positions"], trained) << algorithm;
    }
  }
}

TEST_F(TrainCommand, EachAlgorithmsPolicySaysWhatItIs) {
  for (const std::string algorithm : {"ppo", "sac"}) {
    SCOPED_TRACE(algorithm);
    fs::remove_all(out_);
    const auto r = RunCommand(Sim("train --scenario " + kScenarioB + " --algorithm " + algorithm +
                                  " --fidelity analytic --episodes 1 --set env.episode_duration=20"
                                  " --json --out " +
                                  out_.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto result = nlohmann::json::parse(r.out);
    EXPECT_EQ(result["algorithm"], algorithm);
    EXPECT_EQ(result["action_space"], algorithm == "sac" ? "continuous" : "discrete");
    // The scenario's agent section says dqn: the policy folder, not a flag, says otherwise.
    const auto p = RunCommand(Sim("position --scenario " + kScenarioB +
                                  " --positioner rl --json --set env.episode_duration=20"
                                  " --policy " +
                                  out_.string()));
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(nlohmann::json::parse(p.out)["position"], result["position"]);
  }
  // A continuous flight's trajectory gives each displacement as "dx dy dz".
  std::ifstream trajectory(out_ / "trajectory.csv");
  std::string line;
  std::getline(trajectory, line);
  std::getline(trajectory, line);
  std::vector<std::string> cells;
  std::stringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');)
    cells.push_back(cell);
  ASSERT_EQ(cells.size(), 10u) << line;
  EXPECT_EQ(cells[2], "0") << line;  // the one UAV
  EXPECT_EQ(std::count(cells[3].begin(), cells[3].end(), ' '), 2) << line;
}

TEST_F(TrainCommand, BadInputs) {
  const auto no_policy = RunCommand(Sim("position --scenario " + kScenarioB + " --positioner rl"));
  EXPECT_EQ(no_policy.exit_code, 2);
  EXPECT_NE(no_policy.err.find("--policy: is required for the rl positioner"), std::string::npos)
      << no_policy.err;
  const auto missing = RunCommand(
      Sim("position --scenario " + kScenarioB + " --positioner rl --policy /nonexistent"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/result.json: cannot open: No such file or directory"),
            std::string::npos)
      << missing.err;
  const auto bad_agent = RunCommand(
      Sim("train --scenario " + kScenarioB + " --set agent.gama=0.5 --out " + out_.string()));
  EXPECT_EQ(bad_agent.exit_code, 2);
  EXPECT_NE(bad_agent.err.find("/agent/gama: unknown key \"gama\"; did you mean \"gamma\"?"),
            std::string::npos)
      << bad_agent.err;
  EXPECT_FALSE(fs::exists(out_));
  EXPECT_FALSE(fs::exists(out_.string() + ".partial"));
  const auto bad_algorithm =
      RunCommand(Sim("train --scenario " + kScenarioB + " --algorithm a2c --out " + out_.string()));
  EXPECT_EQ(bad_algorithm.exit_code, 2);
  EXPECT_NE(bad_algorithm.err.find("--algorithm"), std::string::npos) << bad_algorithm.err;
  const auto sac_on_moves = RunCommand(
      Sim("train --scenario " + kScenarioB + " --set agent.algorithm=sac --out " + out_.string()));
  EXPECT_EQ(sac_on_moves.exit_code, 2);
  EXPECT_NE(sac_on_moves.err.find("/agent/algorithm: sac needs env.action_space \"continuous\""),
            std::string::npos)
      << sac_on_moves.err;
  EXPECT_FALSE(fs::exists(out_));
  const auto improvement =
      RunCommand(Sim("train --scenario " + kScenarioB +
                     " --set agent.improvement_reward=true --out " + out_.string()));
  EXPECT_EQ(improvement.exit_code, 2);
  EXPECT_NE(improvement.err.find("/agent/improvement_reward: is learnt only in training across "
                                 "scenarios"),
            std::string::npos)
      << improvement.err;
  EXPECT_EQ(std::count(improvement.err.begin(), improvement.err.end(), '\n'), 1) << improvement.err;
  EXPECT_FALSE(fs::exists(out_));
}

TEST(PositionCommand, BaselineAndCentroid) {
  const auto base =
      RunCommand(Sim("position --scenario " + kScenarioB + " --positioner baseline --json"));
  ASSERT_EQ(base.exit_code, 0) << base.err;
  const auto b = nlohmann::json::parse(base.out);
  EXPECT_EQ(b["position"], (nlohmann::json{50.0, 50.0, 25.0}));
  EXPECT_EQ(b["n_los"], 1);
  const auto centroid =
      RunCommand(Sim("position --scenario " + kScenarioB + " --positioner centroid --json"));
  ASSERT_EQ(centroid.exit_code, 0) << centroid.err;
  // Equal demands: the plain centroid of the UEs, 5 m above the 30 m block.
  EXPECT_EQ(nlohmann::json::parse(centroid.out)["position"], (nlohmann::json{47.5, 37.5, 35.0}));
}

TEST(PositionCommand, OffsetsAroundAGivenPosition) {
  const auto east = RunCommand(Sim("position --scenario " + kScenarioB +
                                   " --positioner offsets --offset 1 --from 50,35,10 --json"));
  ASSERT_EQ(east.exit_code, 0) << east.err;
  EXPECT_EQ(nlohmann::json::parse(east.out)["position"], (nlohmann::json{60.0, 35.0, 10.0}));
  const auto bad = RunCommand(Sim("position --scenario " + kScenarioB +
                                  " --positioner offsets --offset 6 --from 50,35,10"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--offset: is required for the offsets positioner: 1 to 5"),
            std::string::npos)
      << bad.err;
  const auto no_centre =
      RunCommand(Sim("position --scenario " + kScenarioB + " --positioner offsets --offset 2"));
  EXPECT_EQ(no_centre.exit_code, 2);
  EXPECT_NE(no_centre.err.find("--from: give exactly one of"), std::string::npos) << no_centre.err;
}

}  // namespace
}  // namespace rlpos::testing
