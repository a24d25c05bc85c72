#pragma once
// The way round the buildings for the "to_best" move: the shortest path, in moves of env.step,
// on the lattice of a UAV's zone through its initial position (where the coverage map's points
// lie), from any point of it to a target. A move ends where it ends: as in ApplyMove, only its
// end point has to be outside the buildings.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"

namespace rlpos {

class LatticeRoute {
 public:
  // `buildings`: BuildingObstacles(scenario.buildings) (moves.h); both must outlive the route.
  LatticeRoute(const Scenario& scenario, const Obstacles& buildings, std::size_t uav);
  // The first move of a shortest path from UAV `uav`'s place in `from` to `target`, among the
  // moves that the other UAVs leave free. Where there is none (`target` or the UAV off the
  // lattice, the target walled in, every move that brings it nearer taken by another UAV), the
  // straight move of StepTowards, as in a zone of more than 2,000,000 lattice points. (0, 0, 0) at
  // the target.
  Vec3 NextMove(const Vec3& target, const Placement& from);

 private:
  // The node of `p`, or -1 if `p` is not a lattice point of the zone.
  long long NodeOf(const Vec3& p) const;
  Vec3 PointOf(long long node) const;
  // Whether the zone's lattice is small enough to search; builds free_ the first time.
  bool Searchable();
  // Breadth-first distances to `node` over the free nodes.
  void DistancesTo(long long node);

  const Scenario& scenario_;
  const Obstacles& buildings_;
  std::size_t uav_;
  double step_;
  Vec3 first_;                      // the zone's lowest lattice point in each axis
  long long n_[3];                  // nodes per axis
  std::vector<std::uint8_t> free_;  // per node: not inside a building
  long long target_node_ = -1;      // the node `distance_` leads to
  std::vector<int> distance_;       // per node: moves to target_node_, -1 where unreachable
};

}  // namespace rlpos
