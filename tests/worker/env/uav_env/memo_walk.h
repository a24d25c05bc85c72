#pragma once
// What the tests of the placement memos share (placement_memo_test.cc,
// shared_placement_memo_test.cc): a shipped scenario on the analytic evaluator, a random walk of
// its UAVs that comes back to the start often, and a placement scored afresh, which no memo
// answers.
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "common/scenario/building_obstacles.h"
#include "worker/env/gym/moves.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/analytic_evaluator.h"

namespace rlpos::testing {

inline Scenario AnalyticShipped(const std::string& name) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name,
                      {"env.fidelity=analytic"});
}

// The state at `at` from links `fresh` works out now (Score on new links).
inline StepInfo FreshScore(AnalyticEvaluator& fresh, const Placement& at) {
  std::vector<std::vector<UeLink>> links;
  for (std::size_t u = 0; u < at.size(); ++u)
    links.push_back(fresh.LinksAt(u, at[u]));
  std::vector<const std::vector<UeLink>*> views;
  for (const auto& l : links)
    views.push_back(&l);
  return fresh.Score(at, views);
}

// `steps` random moves, seven of each UAV in turn, back at the start every `restart_every`;
// `visit` sees each placement moved to.
template <typename Visit>
void RandomWalk(const Scenario& s, unsigned seed, int steps, int restart_every, Visit&& visit) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> action(0, static_cast<int>(s.env.actions.size()) - 1);
  const Obstacles buildings = BuildingObstacles(s.buildings);
  Placement at = s.InitialPlacement();
  for (int k = 0; k < steps; ++k) {
    const std::size_t uav = static_cast<std::size_t>(k / 7) % at.size();
    at = ApplyMove(s, buildings, uav, action(rng), at);
    visit(at);
    if (k % restart_every == 0)
      at = s.InitialPlacement();
  }
}

}  // namespace rlpos::testing
