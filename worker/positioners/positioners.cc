#include "worker/positioners/positioners.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>

#include "common/scenario/scenario_checks.h"
#include "worker/environment/uav_network.h"
#include "worker/gym/reward.h"
#include "worker/positioners/kmeans.h"
#include "worker/uav_env/analytic_evaluator.h"

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

double RewardOf(const Scenario& s, const Reward& reward, const StepInfo& info) {
  return reward(RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
}

// The coordinate-wise search of OracleSearch for k UAVs, on grid indices.
class PlacementSearch {
 public:
  PlacementSearch(const Scenario& s, AnalyticEvaluator& analytic, const Reward& reward, double step)
      : s_(s), analytic_(analytic), reward_(reward) {
    for (std::size_t u = 0; u < s.uavs.size(); ++u)
      grids_.push_back(ZoneGrid(s, u, step));
    links_.resize(s.uavs.size());
  }

  std::size_t GridSize(std::size_t uav) const { return grids_[uav].size(); }

  // The grid point of UAV `uav` nearest `p`.
  std::size_t Nearest(std::size_t uav, const Vec3& p) const {
    std::size_t best = 0;
    for (std::size_t g = 1; g < grids_[uav].size(); ++g) {
      if (Distance(grids_[uav][g], p) < Distance(grids_[uav][best], p))
        best = g;
    }
    return best;
  }

  bool Valid(const std::vector<std::size_t>& at) const {
    const Placement placement = PlacementOf(at);
    for (std::size_t u = 0; u < at.size(); ++u) {
      if (OverlapsAnother(placement, u, placement[u]))
        return false;
    }
    return true;
  }

  // Descends from `at` until no UAV can improve on its own; returns the end and its score.
  std::pair<std::vector<std::size_t>, StepInfo> Descend(std::vector<std::size_t> at) {
    StepInfo info = Score(at);
    double reward = RewardOf(s_, reward_, info);
    // A UAV's scan is repeated only when another UAV moved since: otherwise it would find the
    // same best point, where it already is.
    const std::size_t k = at.size();
    std::size_t unchanged_scans = 0;
    for (std::size_t u = 0; unchanged_scans < k; u = (u + 1) % k) {
      bool moved = false;
      std::vector<std::size_t> trial = at;
      const Placement placement = PlacementOf(at);
      for (std::size_t g = 0; g < grids_[u].size(); ++g) {
        if (g == at[u] || OverlapsAnother(placement, u, grids_[u][g]))
          continue;
        trial[u] = g;
        const StepInfo candidate = Score(trial);
        const double r = RewardOf(s_, reward_, candidate);
        // Strictly better only: the search cannot cycle, and ties keep the earlier point.
        if (r > reward + 1e-12) {
          reward = r;
          info = candidate;
          at[u] = g;
          moved = true;
        }
      }
      // A scan that moved its UAV leaves it at its best point: it counts as settled.
      unchanged_scans = moved ? 1 : unchanged_scans + 1;
    }
    return {at, info};
  }

  Placement PlacementOf(const std::vector<std::size_t>& at) const {
    Placement placement;
    for (std::size_t u = 0; u < at.size(); ++u)
      placement.push_back(grids_[u][at[u]]);
    return placement;
  }

 private:
  // Each UAV's links at every point of its grid, computed once (the search revisits them all
  // in every round).
  const std::vector<UeLink>& LinksOf(std::size_t uav, std::size_t g) {
    if (links_[uav].empty()) {
      for (const auto& p : grids_[uav])
        links_[uav].push_back(analytic_.LinksAt(uav, p));
    }
    return links_[uav][g];
  }

  StepInfo Score(const std::vector<std::size_t>& at) {
    std::vector<const std::vector<UeLink>*> views;
    for (std::size_t u = 0; u < at.size(); ++u)
      views.push_back(&LinksOf(u, at[u]));
    return analytic_.Score(PlacementOf(at), views);
  }

  const Scenario& s_;
  AnalyticEvaluator& analytic_;
  const Reward& reward_;
  std::vector<std::vector<Vec3>> grids_;
  std::vector<std::vector<std::vector<UeLink>>> links_;
};

std::vector<ScoredPlacement> SearchMany(const Scenario& s, AnalyticEvaluator& analytic,
                                        const Reward& reward, double step,
                                        const OracleOptions& options) {
  PlacementSearch search(s, analytic, reward, step);
  const std::size_t k = s.uavs.size();
  std::vector<std::vector<std::size_t>> starts;
  for (const Placement& seed : {BaselinePlacement(s), CentroidPlacement(s)}) {
    std::vector<std::size_t> at;
    for (std::size_t u = 0; u < k; ++u)
      at.push_back(search.Nearest(u, seed[u]));
    if (search.Valid(at))
      starts.push_back(at);
  }
  std::mt19937_64 rng(options.seed);
  for (int tries = 0; static_cast<int>(starts.size()) < options.starts && tries < 1000; ++tries) {
    std::vector<std::size_t> at;
    for (std::size_t u = 0; u < k; ++u)
      at.push_back(std::uniform_int_distribution<std::size_t>(0, search.GridSize(u) - 1)(rng));
    if (search.Valid(at))
      starts.push_back(at);
  }
  std::map<std::vector<std::size_t>, ScoredPlacement> ends;
  for (const auto& start : starts) {
    const auto [end, info] = search.Descend(start);
    ends[end] = {search.PlacementOf(end), RewardOf(s, reward, info), std::nullopt, info.n_los,
                 info.throughput_mbps};
  }
  std::vector<ScoredPlacement> scored;
  for (auto& [at, placement] : ends)
    scored.push_back(placement);
  return scored;
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
  // Discrete moves reach only the grid of env.step from the initial position; displacements
  // reach any point, which the search samples every kContinuousGridStep metres (one UAV: a
  // 1 m grid of several UAVs' zones is too large to tabulate their links, so they keep env.step).
  const bool fine = s.env.action_space == "continuous" && s.uavs.size() == 1;
  const double step = options.grid_step > 0 ? options.grid_step
                      : fine                ? std::min(s.env.step, kContinuousGridStep)
                                            : s.env.step;
  const auto reward = MakeReward(s.env.reward);
  std::vector<ScoredPlacement> scored;
  {
    AnalyticEvaluator analytic(s);
    if (s.uavs.size() == 1) {
      for (const Vec3& p : ZoneGrid(s, 0, step)) {
        const StepInfo info = analytic.Evaluate({p});
        scored.push_back(
            {{p}, RewardOf(s, *reward, info), std::nullopt, info.n_los, info.throughput_mbps});
      }
    } else {
      scored = SearchMany(s, analytic, *reward, step, options);
    }
  }  // the analytic network is gone before packet-level runs build theirs
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) {
    return a.analytic_reward > b.analytic_reward;
  });
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
