#pragma once
// Positioners: where each compared strategy puts the UAV.
//   baseline  the scenario's initial position
//   centroid  demand-weighted centroid of the UEs, at a height that clears the buildings
//   oracle    exhaustive search of the zone grid scored with the analytic model; the best few
//             re-scored at packet level. The grid is the one the agent moves on (a 1 m grid when
//             it moves by continuous displacements).
//   rl        the trained policy's final greedy position (agent/trainer.h)
#include <optional>
#include <vector>

#include "scenario/scenario.h"

namespace rlpos {

Vec3 BaselinePosition(const Scenario& scenario);

// z = max(10 m, tallest building + 5 m), clamped to the zone; x, y clamped to the zone.
Vec3 CentroidPosition(const Scenario& scenario);

struct ScoredPosition {
  Vec3 position;
  double analytic_reward = 0.0;
  std::optional<double> packet_reward;  // unset: not re-scored at packet level
  int n_los = 0;
  double throughput_mbps = 0.0;
};

// The oracle's grid for an env of continuous actions (m).
constexpr double kContinuousGridStep = 1.0;

struct OracleOptions {
  // m; 0: the env's move step (every position a discrete agent can reach), or
  // kContinuousGridStep for continuous actions
  double grid_step = 0.0;
  int packet_candidates = 3;     // best analytic positions re-scored at packet level (0: none)
  double packet_duration = 2.0;  // s per packet-level re-score
};

// Best first. Every zone grid point outside buildings is scored.
std::vector<ScoredPosition> OracleSearch(const Scenario& scenario, const OracleOptions& options);

}  // namespace rlpos
