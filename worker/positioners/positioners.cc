#include "positioners/positioners.h"

#include <algorithm>
#include <cmath>

#include "environment/uav_network.h"
#include "gym/analytic_evaluator.h"
#include "gym/reward.h"
#include "scenario/scenario_checks.h"

namespace rlpos {

Vec3 BaselinePosition(const Scenario& s) {
  return s.uav.initial;
}

Vec3 CentroidPosition(const Scenario& s) {
  double wx = 0, wy = 0, w = 0;
  for (const auto& ue : s.ues) {
    wx += ue.demand_mbps * ue.position.x;
    wy += ue.demand_mbps * ue.position.y;
    w += ue.demand_mbps;
  }
  double tallest = 0.0;
  for (const auto& b : s.buildings)
    tallest = std::max(tallest, b.height);
  const Box& z = s.uav.zone;
  Vec3 p{std::clamp(wx / w, z.xmin, z.xmax), std::clamp(wy / w, z.ymin, z.ymax),
         std::clamp(std::max(10.0, tallest + 5.0), z.zmin, z.zmax)};
  // Above a building lower than the chosen height the point is free; inside one, climb.
  while (BuildingContaining(s, p) >= 0 && p.z < z.zmax)
    p.z = std::min(p.z + 1.0, z.zmax);
  return p;
}

std::vector<ScoredPosition> OracleSearch(const Scenario& s, const OracleOptions& options) {
  // Discrete moves reach only the grid of env.step from the initial position; displacements
  // reach any point, which the search samples every kContinuousGridStep metres.
  const double step = options.grid_step > 0                  ? options.grid_step
                      : s.env.action_space == "continuous" ? std::min(s.env.step, kContinuousGridStep)
                                                            : s.env.step;
  const auto reward = MakeReward(s.env.reward);
  std::vector<ScoredPosition> scored;
  {
    AnalyticEvaluator analytic(s);
    const Box& z = s.uav.zone;
    // The grid the agent moves on: from the initial position in steps, within the zone.
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
    for (double x : axis(s.uav.initial.x, z.xmin, z.xmax)) {
      for (double y : axis(s.uav.initial.y, z.ymin, z.ymax)) {
        for (double h : axis(s.uav.initial.z, z.zmin, z.zmax)) {
          const Vec3 p{x, y, h};
          if (BuildingContaining(s, p) >= 0)
            continue;
          const StepInfo info = analytic.Evaluate(p);
          scored.push_back(
              {p, (*reward)(RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met)),
               std::nullopt, info.n_los, info.throughput_mbps});
        }
      }
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
      const RunMetrics m = EvaluatePosition(shortened, scored[i].position);
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
