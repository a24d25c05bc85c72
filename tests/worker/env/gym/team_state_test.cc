// The team state a centralised critic sees (worker/env/gym/team_state.h): the team's shares, each
// UAV's load with the UAV itself first and the others nearest first, empty slots, its bounds.
#include "worker/env/gym/team_state.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

// Urban3's three UAVs and five UEs of demands 10 Mbit/s each, as a step could leave them.
Scenario ThreeUavs() {
  Scenario s = ParseScenario(
      ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/urban3.json"));
  s.ues.resize(5);
  for (UeSpec& ue : s.ues)
    ue.demand_mbps = 10.0;
  return s;
}

StepInfo Moment() {
  StepInfo info;
  // UAV 2 is nearer UAV 0 than UAV 1 is (horizontally).
  info.positions = {{0, 0, 40}, {100, 0, 40}, {0, 30, 80}};
  info.serving = {0, 0, 1, 2, 0};
  info.los = {1, 0, 1, 1, 1};
  info.n_los = 4;
  info.demands_met = 2;
  info.throughput_mbps = 20.0;
  return info;
}

TEST(TeamState, HoldsTheTeamsSharesThenEachUavsLoadItselfFirstThenNearestFirst) {
  const Scenario s = ThreeUavs();
  const std::vector<double> state = TeamState(s, Moment(), 0);
  ASSERT_EQ(state.size(), static_cast<std::size_t>(kTeamStateWidth));
  const std::vector<double> want = {
      0.8, 0.4, 0.4, 0.5,  // 4 of 5 in LoS, 2 of 5 met, 20 of 50 Mbit/s, 3 UAVs of 6 slots
      1.0, 0.6, 0.4,       // UAV 0: UEs 0, 1, 4 (0 and 4 in LoS)
      1.0, 0.2, 0.2,       // UAV 2, 30 m away: UE 3
      1.0, 0.2, 0.2,       // UAV 1, 100 m away: UE 2
      0,   0,   0,   0,   0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_DOUBLE_EQ(state[i], want[i]) << "value " << i;
  // From UAV 1: its own load first; UAV 2 (about 104 m) is farther than UAV 0 (100 m).
  const std::vector<double> one = TeamState(s, Moment(), 1);
  EXPECT_DOUBLE_EQ(one[5], 0.2);
  EXPECT_DOUBLE_EQ(one[8], 0.6);
  EXPECT_DOUBLE_EQ(one[11], 0.2);
}

TEST(TeamState, StaysWithinItsBoundsAndRefusesAnInfoOfAnotherScenario) {
  const Scenario s = ThreeUavs();
  StepInfo info = Moment();
  info.throughput_mbps = 500.0;  // more than the demand: clipped
  const BoxSpace box = TeamStateBounds();
  const std::vector<double> state = TeamState(s, info, 2);
  ASSERT_EQ(box.Dim(), state.size());
  for (std::size_t i = 0; i < state.size(); ++i) {
    EXPECT_GE(state[i], box.low[i]) << i;
    EXPECT_LE(state[i], box.high[i]) << i;
  }
  EXPECT_DOUBLE_EQ(state[2], 1.0);
  EXPECT_THROW(TeamState(s, info, 3), std::logic_error);
  info.serving.pop_back();
  EXPECT_THROW(TeamState(s, info, 0), std::logic_error);
}

}  // namespace
}  // namespace rlpos
