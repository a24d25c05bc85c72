#pragma once
// How close rl comes to the oracle: for every rl placement of a campaign (one per scenario,
// algorithm and train seed, and one per scenario and named policy), its reward and the oracle's at
// the same scenario, read from the evals' `reward` metric (the env's reward by the analytic model,
// metrics/eval_metrics.h). The report's optimality section and the campaign page read these rows;
// the statistics over them are coordinator/reporting/optimality.h.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rlpos {

class Database;

struct OptimalityRow {
  std::string scenario;
  int uavs = 1;  // UAVs of the scenario
  // What the train job trained (its result's "algorithm"), "" unknown; a named policy's label
  // (rl+<name>), which no trained algorithm is.
  std::string algorithm;
  std::uint64_t train_seed = 0;  // 0 for a named policy
  std::string label;             // the rl eval label: rl, rl@ppo, rl@dqn@seed2, rl+<name>
  int runs = 0;                  // its succeeded evals with a reward
  double rl_reward = 0;          // mean over those runs (the analytic model: the same in each)
  double oracle_reward = 0;      // the scenario's oracle's, the same way
  // rl's reward over the oracle's; nullopt when the oracle's is not positive (no ratio says
  // anything there). Several UAVs: against the coordinate-descent oracle, which rl may beat.
  std::optional<double> Ratio() const;
};

// One row per rl eval label of a scenario that has both rl and oracle evals with a reward
// (evals recorded before the reward metric have none and are left out). Scenarios in campaign
// order, then the train jobs' order (algorithms dqn, ppo, sac; seeds as listed).
std::vector<OptimalityRow> ReadOptimalityRows(Database& db, const std::string& campaign_id);

}  // namespace rlpos
