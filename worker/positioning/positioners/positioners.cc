#include "worker/positioning/positioners/positioners.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "common/scenario/scenario_checks.h"
#include "worker/env/gym/reward.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/kmeans.h"
#include "worker/positioning/positioners/placement_search.h"

namespace rlpos {
namespace {

double Distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

// Above (x, y) at max(10 m, tallest building + 5 m), within UAV `uav`'s zone; climbs out of a
// building lower than the zone's ceiling.
Vec3 HoverAbove(const Scenario& s, std::size_t uav, double x, double y) {
  double tallest = 0.0;
  for (const auto& b : s.buildings)
    tallest = std::max(tallest, b.height);
  const Box& z = s.uavs[uav].zone;
  Vec3 p{std::clamp(x, z.xmin, z.xmax), std::clamp(y, z.ymin, z.ymax),
         std::clamp(std::max(10.0, tallest + 5.0), z.zmin, z.zmax)};
  while (BuildingContaining(s, p) >= 0 && p.z < z.zmax)
    p.z = std::min(p.z + 1.0, z.zmax);
  return p;
}

}  // namespace

Placement BaselinePlacement(const Scenario& s) {
  return s.InitialPlacement();
}

Placement CentroidPlacement(const Scenario& s) {
  const std::size_t k = s.uavs.size();
  const std::vector<Cluster> clusters = KMeansUes(s, k);
  // Cluster c goes to UAV order[c]: the matching of least total distance (k <= 8: 8! tries).
  std::vector<std::vector<double>> cost(k, std::vector<double>(k));
  for (std::size_t c = 0; c < k; ++c) {
    for (std::size_t u = 0; u < k; ++u)
      cost[c][u] = Distance(HoverAbove(s, u, clusters[c].x, clusters[c].y), s.uavs[u].initial);
  }
  std::vector<std::size_t> order(k), best;
  std::iota(order.begin(), order.end(), 0);
  double least = std::numeric_limits<double>::infinity();
  do {
    double total = 0.0;
    for (std::size_t c = 0; c < k; ++c)
      total += cost[c][order[c]];
    if (total < least) {
      least = total;
      best = order;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  Placement placement(k);
  for (std::size_t c = 0; c < k; ++c)
    placement[best[c]] = HoverAbove(s, best[c], clusters[c].x, clusters[c].y);
  // Two clusters on one spot (fewer UE positions than UAVs): stack the later UAV higher.
  for (std::size_t u = 1; u < k; ++u) {
    while (OverlapsAnother(placement, u, placement[u]) && placement[u].z < s.uavs[u].zone.zmax)
      placement[u].z = std::min(placement[u].z + kMinUavSeparation, s.uavs[u].zone.zmax);
  }
  return placement;
}

std::vector<Vec3> ZoneGrid(const Scenario& s, std::size_t uav, double step) {
  const Box& z = s.uavs[uav].zone;
  const Vec3& initial = s.uavs[uav].initial;
  auto axis = [&](double start, double lo, double hi) {
    std::vector<double> values;
    for (double v = start; v >= lo - 1e-9; v -= step)
      values.push_back(v);
    for (double v = start + step; v <= hi + 1e-9; v += step)
      values.push_back(v);
    values.push_back(lo);
    values.push_back(hi);
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                 values.end());
    return values;
  };
  std::vector<Vec3> grid;
  for (double x : axis(initial.x, z.xmin, z.xmax)) {
    for (double y : axis(initial.y, z.ymin, z.ymax)) {
      for (double h : axis(initial.z, z.zmin, z.zmax)) {
        const Vec3 p{x, y, h};
        if (BuildingContaining(s, p) < 0)
          grid.push_back(p);
      }
    }
  }
  return grid;
}

std::vector<ScoredPlacement> OracleSearch(const Scenario& s, const OracleOptions& options) {
  const auto reward = MakeReward(s.env.reward);
  std::vector<ScoredPlacement> scored;
  {
    AnalyticEvaluator analytic(s);
    // One UAV: each grid point is scored once, its links are not worth keeping. k UAVs: the
    // search revisits every point in every round.
    ZoneLinkTable links(s, OracleGridStep(s, options),
                        s.uavs.size() == 1 ? 0 : std::numeric_limits<std::size_t>::max());
    scored = AnalyticOracle(s, analytic, links, *reward, options);
  }  // the analytic network is gone before packet-level runs build theirs
  const int k = std::min<int>(options.packet_candidates, static_cast<int>(scored.size()));
  if (k > 0) {
    Scenario shortened = s;
    shortened.simulation.duration = options.packet_duration + s.simulation.warmup;
    for (int i = 0; i < k; ++i) {
      const RunMetrics m = EvaluatePosition(shortened, scored[i].placement);
      scored[i].packet_reward =
          (*reward)(RewardInputOf(s, m.n_los, m.aggregate_throughput_mbps, m.demands_met));
    }
    std::stable_sort(scored.begin(), scored.begin() + k, [](const auto& a, const auto& b) {
      return a.packet_reward > b.packet_reward;
    });
  }
  return scored;
}

}  // namespace rlpos
