// The shipped policies flown without libtorch (PpoGreedyPolicy, as rlpos-sim position flies a
// policy for any scenario) end where PpoAgent's flight ends, bit for bit, in generated scenarios
// they never saw: one UAV, and four. GeneralPlacement places the UAVs at the best step of that
// flight, not at its last, and several UAVs at the best of flights from several starts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/agent_base/greedy_flight.h"
#include "worker/learning/agent_base/ppo_greedy_policy.h"
#include "worker/learning/agent_base/trainer.h"
#include "worker/learning/policy_folder/general_placement.h"
#include "worker/learning/policy_folder/policy_folder.h"

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

// A generated scenario as `position` meets it: written to a file, placed by GeneralPlacement.
struct PlacedScenario {
  Scenario scenario;  // with the policy's env and agent, as the placement flies it
  Placement placed;
};

PlacedScenario PlaceGenerated(const sim::PolicyFolder& folder, GeneratorStyle style, int uavs,
                              std::uint64_t seed) {
  GeneratorOptions options;
  options.seed = seed;
  options.style = style;
  options.uavs = uavs;
  const GeneratedScenario generated = GenerateScenario(options);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("rlpos-shipped-placement-" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << generated.json_text;
  sim::CommonOptions common;
  common.scenario_file = file.string();
  PlacedScenario r{generated.scenario, sim::GeneralPlacement(folder, common)};
  std::filesystem::remove(file);
  r.scenario.env = folder.trained.env;
  r.scenario.agent = folder.trained.agent;
  return r;
}

void ExpectPlacedAt(const Placement& placed, const GreedyFlight& flight) {
  ASSERT_EQ(placed.size(), flight.final_info.positions.size());
  for (std::size_t u = 0; u < placed.size(); ++u) {
    EXPECT_EQ(placed[u].x, flight.final_info.positions[u].x) << u;
    EXPECT_EQ(placed[u].y, flight.final_info.positions[u].y) << u;
    EXPECT_EQ(placed[u].z, flight.final_info.positions[u].z) << u;
  }
}

// generalist-multi's placement in a generated scenario, and the env and greedy policy that fly
// its flights again by hand.
struct MultiPlacement {
  MultiPlacement(GeneratorStyle style, int uavs, std::uint64_t seed)
      : folder(sim::ReadPolicyFolder(std::string(RLPOS_SOURCE_DIR) + "/policies/generalist-multi")),
        placed(PlaceGenerated(folder, style, uavs, seed)),
        env(placed.scenario),
        greedy(placed.scenario.agent, static_cast<int>(env.ObservationSpace().Dim()),
               env.ActionSpace().n, env.UeSlots()),
        episode(GreedyEpisodeOptions(placed.scenario.agent)) {
    greedy.Load(folder.dir);
  }
  GreedyFlight FromTheBaseline() {
    return FlyGreedyToBest(env, greedy, folder.eval_run, episode, kGeneralPatienceSteps);
  }
  GreedyFlight PlacementFlights() {
    return FlyGeneralPlacement(env, greedy, folder.eval_run, episode);
  }

  sim::PolicyFolder folder;
  PlacedScenario placed;
  UavPositioningEnv env;
  PpoGreedyPolicy greedy;
  EpisodeOptions episode;
};

TEST(ShippedPolicyFlight, APlacementIsTheBestStepOfTheFlightNotItsLast) {
  // Six UAVs (verify-many's campus-6uav-s36101): the flight wanders after its best for hundreds
  // of steps before a state repeats, and ends lower.
  MultiPlacement m(GeneratorStyle::kCampus, 6, 36101);
  const GreedyFlight last = FlyGreedy(m.env, m.greedy, m.folder.eval_run, m.episode);
  const GreedyFlight best = m.FromTheBaseline();
  EXPECT_GT(best.final_reward, last.final_reward);
  EXPECT_LT(best.steps_flown, last.steps_flown);
  // The placement's first flight is that one; it keeps the best of it and of the others.
  const GreedyFlight placement = m.PlacementFlights();
  EXPECT_GE(placement.final_reward, best.final_reward);
  ExpectPlacedAt(m.placed.placed, placement);
}

TEST(ShippedPolicyFlight, SeveralUavsArePlacedAtTheBestOfFlightsFromSeveralStarts) {
  // Two UAVs (probe-many's urban-2uav-s112001): from the baseline the policy stops short, with
  // 10 of 14 UEs in LoS; a flight from another start does better.
  MultiPlacement m(GeneratorStyle::kUrban, 2, 112001);
  const GreedyFlight from_baseline = m.FromTheBaseline();
  const GreedyFlight placement = m.PlacementFlights();
  EXPECT_GT(placement.final_reward, from_baseline.final_reward);
  EXPECT_GT(placement.final_info.n_los, from_baseline.final_info.n_los);
  EXPECT_GT(placement.steps_flown, from_baseline.steps_flown);
  EXPECT_LE(placement.steps_flown,
            std::max(from_baseline.steps_flown, kGeneralPlacementStepBudget));
  ExpectPlacedAt(m.placed.placed, placement);
}

}  // namespace
}  // namespace rlpos::shipped_policy_flight_test
