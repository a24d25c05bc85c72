#pragma once
// Positioners: where each compared strategy puts the UAVs.
//   baseline  the scenario's initial positions
//   centroid  one UAV: the demand-weighted centroid of the UEs; k UAVs: the centroids of a
//             deterministic k-means of the UEs (kmeans.h). Heights clear the buildings.
//   oracle    a search of the zone grid scored with the analytic model; the best few re-scored at
//             packet level. The grid is the one the agent moves on (one UAV moving by continuous
//             displacements: a 1 m grid). One UAV: every grid point (the grid's optimum).
//             k UAVs: coordinate descent from several starts on the env.step grid (below).
//   rl        the trained policy's final greedy placement (agent/trainer.h)
#include <cstdint>
#include <optional>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

Placement BaselinePlacement(const Scenario& scenario);

// One UAV: z = max(10 m, tallest building + 5 m), clamped to the zone; x, y clamped to the zone.
// k UAVs: the same for each k-means cluster, the clusters matched to the UAVs so that the sum
// of distances from their initial positions is least.
Placement CentroidPlacement(const Scenario& scenario);

struct ScoredPlacement {
  Placement placement;
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
  int packet_candidates = 3;     // best analytic placements re-scored at packet level (0: none)
  double packet_duration = 2.0;  // s per packet-level re-score
  // k UAVs: the searches' starts: the baseline, the centroid placement, then random grid
  // placements drawn with `seed` (deterministic).
  int starts = 8;
  std::uint64_t seed = 1;
};

// Best first.
// One UAV: every zone grid point outside buildings is scored: the best is the grid's optimum.
// k UAVs: from each start, each UAV in turn moves to the best point of its whole zone grid with
// the others fixed, until a round moves none. Each search ends in a placement that no single
// UAV can improve by moving anywhere on its grid (a coordinate-wise optimum); the result is the
// best of the starts, not a proven joint optimum (the joint grid has |grid|^k points). Returned:
// the distinct end placements of the starts.
std::vector<ScoredPlacement> OracleSearch(const Scenario& scenario, const OracleOptions& options);

// The grid the agent moves on within UAV `uav`'s zone, outside buildings: from its initial
// position in steps of `step`, plus the zone's walls.
std::vector<Vec3> ZoneGrid(const Scenario& scenario, std::size_t uav, double step);

}  // namespace rlpos
