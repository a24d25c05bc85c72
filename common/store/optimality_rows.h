#pragma once
// How close each placement comes to the oracle: for every placement of a campaign (rl: one per
// scenario, algorithm and train seed; one per scenario and named policy; one per scenario and
// other positioner, the oracle's own included), its reward and the oracle's at the same scenario,
// read from the evals' `reward` metric (the env's reward by the analytic model,
// metrics/eval_metrics.h), and the seconds its placement took. The report's optimality section
// and the campaign page read these rows; the statistics over them are
// coordinator/reporting/optimality.h.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rlpos {

class Database;

struct OptimalityRow {
  std::string scenario;
  int uavs = 1;  // UAVs of the scenario
  // What the train job trained (its result's "algorithm"), "" unknown; for a placement of a
  // position job, its label (rl+<name>, centroid, oracle, ...), which no trained algorithm is.
  std::string algorithm;
  std::uint64_t train_seed = 0;  // 0 for a position job's placement
  // The eval label: rl, rl@ppo, rl@dqn@seed2 (trained), rl+<name> (a named policy), baseline,
  // centroid, oracle.
  std::string label;
  bool trained = false;      // placed by a train job (per-scenario training), not a position job
  int runs = 0;              // its succeeded evals with a reward
  double rl_reward = 0;      // mean over those runs (the analytic model: the same in each)
  double oracle_reward = 0;  // the scenario's oracle's, the same way
  // Wall seconds of the job that found the placement (the training, or the position job: for a
  // named policy, loading it and its flight), on its worker; a cached job's are its source's.
  std::optional<double> placement_s;
  // rl's reward over the oracle's; nullopt when the oracle's is not positive (no ratio says
  // anything there). Several UAVs: against the coordinate-descent oracle, which rl may beat.
  std::optional<double> Ratio() const;
  // An rl placement: trained or a named policy's (the rows the report lists when under 0.95).
  bool IsRl() const;
  // The oracle's own placement (ratio 1: there for its time, compared with nothing).
  bool IsOracle() const;
};

// One row per eval label (offsets excepted) of a scenario that has oracle evals with a reward
// (evals recorded before the reward metric have none and are left out). Scenarios in campaign
// order; in each, the train jobs' order (algorithms dqn, ppo, sac; seeds as listed), then the
// position jobs'.
std::vector<OptimalityRow> ReadOptimalityRows(Database& db, const std::string& campaign_id);

}  // namespace rlpos
