// The shipped policies flown without libtorch (PpoGreedyPolicy, as rlpos-sim position flies a
// policy for any scenario) end where PpoAgent's flight ends, bit for bit, in generated scenarios
// they never saw: one UAV, and four. GeneralPlacement places the UAVs at the best step of that
// flight, not at its last.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/scenario_generator/scenario_generator.h"
#include "worker/agent/greedy_flight.h"
#include "worker/agent/ppo_agent.h"
#include "worker/agent/ppo_greedy_policy.h"
#include "worker/agent/trainer.h"
#include "worker/policy_folder/general_placement.h"
#include "worker/policy_folder/policy_folder.h"
#include "worker/uav_env/uav_positioning_env.h"

namespace rlpos::shipped_policy_flight_test {
namespace {

void ExpectTheSameFlight(const std::string& policy, GeneratorStyle style, int uavs) {
  const std::string dir = std::string(RLPOS_SOURCE_DIR) + "/policies/" + policy;
  const sim::PolicyFolder folder = sim::ReadPolicyFolder(dir);
  GeneratorOptions options;
  options.seed = 12;
  options.style = style;
  options.uavs = uavs;
  Scenario s = GenerateScenario(options).scenario;
  s.env = folder.trained.env;
  s.agent = folder.trained.agent;
  UavPositioningEnv env(s);
  const int dim = static_cast<int>(env.ObservationSpace().Dim());
  PpoAgent agent(s.agent, dim, env.ActionSpace().n, 0, env.UeSlots());
  agent.Load(dir);
  PpoGreedyPolicy greedy(s.agent, dim, env.ActionSpace().n, env.UeSlots());
  greedy.Load(dir);
  const EpisodeOptions episode = GreedyEpisodeOptions(s.agent);
  const GreedyFlight want = FlyGreedy(env, agent, folder.eval_run, episode);
  const GreedyFlight got = FlyGreedy(env, greedy, folder.eval_run, episode);
  ASSERT_EQ(got.final_info.positions.size(), static_cast<std::size_t>(uavs));
  for (std::size_t u = 0; u < got.final_info.positions.size(); ++u) {
    EXPECT_EQ(got.final_info.positions[u].x, want.final_info.positions[u].x) << policy;
    EXPECT_EQ(got.final_info.positions[u].y, want.final_info.positions[u].y) << policy;
    EXPECT_EQ(got.final_info.positions[u].z, want.final_info.positions[u].z) << policy;
  }
  EXPECT_EQ(got.final_reward, want.final_reward) << policy;
  EXPECT_EQ(got.steps_flown, want.steps_flown) << policy;
  EXPECT_GT(got.steps_flown, 1) << policy;
  // The flight left the baseline.
  const Placement start = s.InitialPlacement();
  bool moved = false;
  for (std::size_t u = 0; u < start.size(); ++u)
    moved = moved || start[u].x != got.final_info.positions[u].x ||
            start[u].y != got.final_info.positions[u].y ||
            start[u].z != got.final_info.positions[u].z;
  EXPECT_TRUE(moved) << policy;
}

TEST(ShippedPolicyFlight, WithoutLibtorchEndsWherePpoAgentsFlightEnds) {
  ExpectTheSameFlight("generalist-1uav", GeneratorStyle::kUrban, 1);
  ExpectTheSameFlight("generalist-multi", GeneratorStyle::kCampus, 4);
}

TEST(ShippedPolicyFlight, APlacementIsTheBestStepOfTheFlightNotItsLast) {
  // Six UAVs (verify-many's campus-6uav-s36101): the flight wanders after its best for hundreds
  // of steps before a state repeats, and ends lower.
  const std::string dir = std::string(RLPOS_SOURCE_DIR) + "/policies/generalist-multi";
  const sim::PolicyFolder folder = sim::ReadPolicyFolder(dir);
  GeneratorOptions options;
  options.seed = 36101;
  options.style = GeneratorStyle::kCampus;
  options.uavs = 6;
  const GeneratedScenario generated = GenerateScenario(options);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("rlpos-best-of-flight-" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << generated.json_text;
  sim::CommonOptions common;
  common.scenario_file = file.string();
  const Placement placed = sim::GeneralPlacement(folder, common);
  std::filesystem::remove(file);

  Scenario s = generated.scenario;
  s.env = folder.trained.env;
  s.agent = folder.trained.agent;
  UavPositioningEnv env(s);
  const int dim = static_cast<int>(env.ObservationSpace().Dim());
  PpoGreedyPolicy greedy(s.agent, dim, env.ActionSpace().n, env.UeSlots());
  greedy.Load(dir);
  const EpisodeOptions episode = GreedyEpisodeOptions(s.agent);
  const GreedyFlight last = FlyGreedy(env, greedy, folder.eval_run, episode);
  const GreedyFlight best =
      FlyGreedyToBest(env, greedy, folder.eval_run, episode, kGeneralPatienceSteps);
  EXPECT_GT(best.final_reward, last.final_reward);
  EXPECT_LT(best.steps_flown, last.steps_flown);
  ASSERT_EQ(placed.size(), best.final_info.positions.size());
  for (std::size_t u = 0; u < placed.size(); ++u) {
    EXPECT_EQ(placed[u].x, best.final_info.positions[u].x) << u;
    EXPECT_EQ(placed[u].y, best.final_info.positions[u].y) << u;
    EXPECT_EQ(placed[u].z, best.final_info.positions[u].z) << u;
  }
}

}  // namespace
}  // namespace rlpos::shipped_policy_flight_test
