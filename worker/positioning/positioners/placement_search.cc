#include "worker/positioning/positioners/placement_search.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <unordered_map>

#include "common/scenario/scenario_checks.h"

namespace rlpos {
namespace {

double GridDistance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

double RewardOf(const Scenario& s, const Reward& reward, const StepInfo& info) {
  return reward(RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
}

bool SamePosition(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

struct IndexHash {
  std::size_t operator()(const std::vector<std::size_t>& at) const {
    std::size_t h = at.size();
    for (std::size_t i : at)
      h = h * 1000003u ^ i;
    return h;
  }
};

// The coordinate-wise search of OracleSearch for k UAVs, on grid indices.
class PlacementSearch {
 public:
  PlacementSearch(const Scenario& s, AnalyticEvaluator& analytic, ZoneLinkTable& links,
                  const Reward& reward)
      : s_(s), analytic_(analytic), links_(links), reward_(reward) {}

  std::size_t GridSize(std::size_t uav) const { return links_.Grid(uav).size(); }

  // The grid point of UAV `uav` nearest `p`.
  std::size_t Nearest(std::size_t uav, const Vec3& p) const {
    const std::vector<Vec3>& grid = links_.Grid(uav);
    std::size_t best = 0;
    for (std::size_t g = 1; g < grid.size(); ++g) {
      if (GridDistance(grid[g], p) < GridDistance(grid[best], p))
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
    double reward = RewardAt(at);
    // A UAV's scan is repeated only when another UAV moved since: otherwise it would find the
    // same best point, where it already is.
    const std::size_t k = at.size();
    std::size_t unchanged_scans = 0;
    for (std::size_t u = 0; unchanged_scans < k; u = (u + 1) % k) {
      bool moved = false;
      std::vector<std::size_t> trial = at;
      const Placement placement = PlacementOf(at);
      for (std::size_t g = 0; g < GridSize(u); ++g) {
        if (g == at[u] || OverlapsAnother(placement, u, links_.Grid(u)[g]))
          continue;
        trial[u] = g;
        const double r = RewardAt(trial);
        // Strictly better only: the search cannot cycle, and ties keep the earlier point.
        if (r > reward + 1e-12) {
          reward = r;
          at[u] = g;
          moved = true;
        }
      }
      // A scan that moved its UAV leaves it at its best point: it counts as settled.
      unchanged_scans = moved ? 1 : unchanged_scans + 1;
    }
    return {at, Score(at)};
  }

  Placement PlacementOf(const std::vector<std::size_t>& at) const {
    Placement placement;
    for (std::size_t u = 0; u < at.size(); ++u)
      placement.push_back(links_.Grid(u)[at[u]]);
    return placement;
  }

 private:
  StepInfo Score(const std::vector<std::size_t>& at) {
    std::vector<const std::vector<UeLink>*> views;
    for (std::size_t u = 0; u < at.size(); ++u)
      views.push_back(&links_.Links(analytic_, u, at[u]));
    return analytic_.Score(PlacementOf(at), views);
  }

  // The reward at `at`, each placement scored once per search: the starts' descents and their
  // closing scans revisit the same placements (a pure function of them: the same numbers).
  double RewardAt(const std::vector<std::size_t>& at) {
    const auto [it, added] = rewards_.try_emplace(at, 0.0);
    if (added)
      it->second = RewardOf(s_, reward_, Score(at));
    return it->second;
  }

  const Scenario& s_;
  AnalyticEvaluator& analytic_;
  ZoneLinkTable& links_;
  const Reward& reward_;
  std::unordered_map<std::vector<std::size_t>, double, IndexHash> rewards_;
};

std::vector<ScoredPlacement> SearchMany(const Scenario& s, AnalyticEvaluator& analytic,
                                        ZoneLinkTable& links, const Reward& reward,
                                        const OracleOptions& options,
                                        const std::vector<Placement>& extra_starts) {
  PlacementSearch search(s, analytic, links, reward);
  const std::size_t k = s.uavs.size();
  std::vector<std::vector<std::size_t>> starts;
  auto add_start = [&](const Placement& seed) {
    std::vector<std::size_t> at;
    for (std::size_t u = 0; u < k; ++u)
      at.push_back(search.Nearest(u, seed[u]));
    if (search.Valid(at))
      starts.push_back(at);
  };
  add_start(BaselinePlacement(s));
  add_start(CentroidPlacement(s));
  std::mt19937_64 rng(options.seed);
  for (int tries = 0; static_cast<int>(starts.size()) < options.starts && tries < 1000; ++tries) {
    std::vector<std::size_t> at;
    for (std::size_t u = 0; u < k; ++u)
      at.push_back(std::uniform_int_distribution<std::size_t>(0, search.GridSize(u) - 1)(rng));
    if (search.Valid(at))
      starts.push_back(at);
  }
  // After the random ones, which are then drawn as without them: the starts are a superset, so
  // the best end is at least as good.
  for (const Placement& seed : extra_starts)
    add_start(seed);
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

ZoneLinkTable::ZoneLinkTable(const Scenario& s, double step, std::size_t budget_bytes)
    : n_ues_(s.ues.size()) {
  std::size_t points = 0;
  for (std::size_t u = 0; u < s.uavs.size(); ++u) {
    grids_.push_back(ZoneGrid(s, u, step));
    points += grids_.back().size();
  }
  tabulate_ = points * n_ues_ * sizeof(UeLink) <= budget_bytes;
  table_.resize(grids_.size());
  scratch_.resize(grids_.size());
}

const std::vector<UeLink>& ZoneLinkTable::Links(AnalyticEvaluator& analytic, std::size_t uav,
                                                std::size_t g) {
  if (!tabulate_) {
    scratch_[uav] = analytic.LinksAt(uav, grids_[uav][g]);
    return scratch_[uav];
  }
  std::vector<std::vector<UeLink>>& table = table_[uav];
  if (table.empty()) {
    for (const Vec3& p : grids_[uav])
      table.push_back(analytic.LinksAt(uav, p));
  }
  return table[g];
}

void ZoneLinkTable::MoveUes(AnalyticEvaluator& analytic, const std::vector<Vec3>& before) {
  const std::vector<Vec3>& now = analytic.UePositions();
  for (std::size_t u = 0; u < table_.size(); ++u) {
    if (table_[u].empty())
      continue;
    for (std::size_t i = 0; i < n_ues_; ++i) {
      if (SamePosition(before[i], now[i]))
        continue;
      for (std::size_t g = 0; g < grids_[u].size(); ++g)
        table_[u][g][i] = analytic.LinkAt(u, i, grids_[u][g]);
    }
  }
}

double OracleGridStep(const Scenario& s, const OracleOptions& options) {
  // Discrete moves reach only the grid of env.step from the initial position; displacements
  // reach any point, which the search samples every kContinuousGridStep metres (one UAV: a
  // 1 m grid of several UAVs' zones is too large to tabulate their links, so they keep env.step).
  const bool fine = s.env.action_space == "continuous" && s.uavs.size() == 1;
  return options.grid_step > 0 ? options.grid_step
         : fine                ? std::min(s.env.step, kContinuousGridStep)
                               : s.env.step;
}

std::vector<ScoredPlacement> AnalyticOracle(const Scenario& s, AnalyticEvaluator& analytic,
                                            ZoneLinkTable& links, const Reward& reward,
                                            const OracleOptions& options,
                                            const std::vector<Placement>& extra_starts) {
  std::vector<ScoredPlacement> scored;
  if (s.uavs.size() == 1) {
    const std::vector<Vec3>& grid = links.Grid(0);
    for (std::size_t g = 0; g < grid.size(); ++g) {
      const StepInfo info = analytic.Score({grid[g]}, {&links.Links(analytic, 0, g)});
      scored.push_back(
          {{grid[g]}, RewardOf(s, reward, info), std::nullopt, info.n_los, info.throughput_mbps});
    }
  } else {
    scored = SearchMany(s, analytic, links, reward, options, extra_starts);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) {
    return a.analytic_reward > b.analytic_reward;
  });
  return scored;
}

}  // namespace rlpos
