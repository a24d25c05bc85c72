#include "worker/env/gym/lattice_route.h"

#include <cmath>
#include <deque>

#include "worker/env/gym/moves.h"

namespace rlpos {

namespace {

constexpr double kOnLattice = 1e-6;  // metres: a point this close to a node is on it
// A zone with more lattice points than this (a fine env.step over a large zone) keeps the
// straight move: 5 bytes a point, so at most 10 MB per UAV, and a search of at most that many.
constexpr long long kMaxNodes = 2'000'000;

// The lowest lattice coordinate through `origin` at or above `low`, and how many fit to `high`.
void AxisOf(double origin, double step, double low, double high, double& first, long long& n) {
  first = origin - step * std::floor((origin - low) / step + kOnLattice);
  n = high + kOnLattice >= first
          ? static_cast<long long>(std::floor((high - first) / step + kOnLattice)) + 1
          : 0;
}

}  // namespace

LatticeRoute::LatticeRoute(const Scenario& scenario, const Obstacles& buildings, std::size_t uav)
    : scenario_(scenario), buildings_(buildings), uav_(uav), step_(scenario.env.step) {
  const Box& zone = scenario.uavs.at(uav).zone;
  const Vec3& origin = scenario.uavs[uav].initial;
  AxisOf(origin.x, step_, zone.xmin, zone.xmax, first_.x, n_[0]);
  AxisOf(origin.y, step_, zone.ymin, zone.ymax, first_.y, n_[1]);
  AxisOf(origin.z, step_, zone.zmin, zone.zmax, first_.z, n_[2]);
}

bool LatticeRoute::Searchable() {
  const long long nodes = n_[0] * n_[1] * n_[2];
  if (nodes < 1 || nodes > kMaxNodes)
    return false;
  if (free_.empty()) {  // built on the first move asked for, not with every env
    free_.assign(static_cast<std::size_t>(nodes), 0);
    for (long long node = 0; node < nodes; ++node)
      free_[static_cast<std::size_t>(node)] = buildings_.SolidAt(PointOf(node)) < 0;
  }
  return true;
}

long long LatticeRoute::NodeOf(const Vec3& p) const {
  const double v[3] = {p.x - first_.x, p.y - first_.y, p.z - first_.z};
  long long node = 0;
  for (int axis = 2; axis >= 0; --axis) {
    const double k = std::round(v[axis] / step_);
    if (std::abs(v[axis] - k * step_) > kOnLattice || k < 0 || k >= n_[axis])
      return -1;
    node = node * n_[axis] + static_cast<long long>(k);
  }
  return node;
}

Vec3 LatticeRoute::PointOf(long long node) const {
  const long long i = node % n_[0], j = (node / n_[0]) % n_[1], k = node / (n_[0] * n_[1]);
  return {first_.x + static_cast<double>(i) * step_, first_.y + static_cast<double>(j) * step_,
          first_.z + static_cast<double>(k) * step_};
}

void LatticeRoute::DistancesTo(long long node) {
  target_node_ = node;
  distance_.assign(free_.size(), -1);
  if (!free_[static_cast<std::size_t>(node)])
    return;
  const long long stride[3] = {1, n_[0], n_[0] * n_[1]};
  std::deque<long long> queue{node};
  distance_[static_cast<std::size_t>(node)] = 0;
  while (!queue.empty()) {
    const long long at = queue.front();
    queue.pop_front();
    const long long index[3] = {at % n_[0], (at / n_[0]) % n_[1], at / (n_[0] * n_[1])};
    for (int axis = 0; axis < 3; ++axis) {
      for (const int sign : {-1, 1}) {
        const long long k = index[axis] + sign;
        if (k < 0 || k >= n_[axis])
          continue;
        const long long next = at + sign * stride[axis];
        const auto slot = static_cast<std::size_t>(next);
        if (!free_[slot] || distance_[slot] >= 0)
          continue;
        distance_[slot] = distance_[static_cast<std::size_t>(at)] + 1;
        queue.push_back(next);
      }
    }
  }
}

Vec3 LatticeRoute::NextMove(const Vec3& target, const Placement& from) {
  const Vec3& at = from.at(uav_);
  const long long goal = NodeOf(target), here = NodeOf(at);
  if (goal < 0 || here < 0 || !Searchable())
    return StepTowards(scenario_, buildings_, uav_, target, from);
  if (goal != target_node_)
    DistancesTo(goal);
  const int to_go = distance_[static_cast<std::size_t>(here)];
  if (to_go == 0)
    return {0, 0, 0};
  if (to_go < 0)  // the target is walled in
    return StepTowards(scenario_, buildings_, uav_, target, from);
  // Every move one nearer (each neighbour is one nearer, as near, or one further): of those the
  // other UAVs leave free, the one along the largest remaining offset (x, y, z on a tie), as the
  // straight move would pick where nothing is in the way.
  const double offset[3] = {target.x - at.x, target.y - at.y, target.z - at.z};
  Vec3 best{0, 0, 0};
  double best_offset = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    for (const int sign : {1, -1}) {
      Vec3 delta{0, 0, 0};
      (axis == 0 ? delta.x : axis == 1 ? delta.y : delta.z) = sign * step_;
      const long long next = NodeOf({at.x + delta.x, at.y + delta.y, at.z + delta.z});
      if (next < 0 || distance_[static_cast<std::size_t>(next)] != to_go - 1 ||
          std::abs(offset[axis]) <= best_offset)
        continue;
      const Vec3 to = DisplacementTarget(scenario_, buildings_, uav_, delta, from);
      if (to.x == at.x && to.y == at.y && to.z == at.z)
        continue;  // another UAV is there
      best = delta;
      best_offset = std::abs(offset[axis]);
    }
  }
  return best_offset < 0.0 ? StepTowards(scenario_, buildings_, uav_, target, from) : best;
}

}  // namespace rlpos
