#include "worker/env/uav_env/model_observations.h"

#include <algorithm>
#include <cmath>

#include "worker/env/gym/general_observation.h"
#include "worker/env/gym/moves.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/one_uav_moves.h"

namespace rlpos {
namespace {

// The lattice value (through `origin`, `step` apart) nearest `target` within [low, high]; the
// origin itself when no lattice value lies there.
double NearestOnLattice(double target, double origin, double step, double low, double high) {
  double v = origin + std::round((target - origin) / step) * step;
  if (v > high)
    v -= step * std::ceil((v - high) / step);
  if (v < low)
    v += step * std::ceil((low - v) / step);
  return v >= low && v <= high ? v : origin;
}

// Every lattice altitude of the zone, lowest first.
std::vector<double> LatticeAltitudes(double origin, double step, double low, double high) {
  std::vector<double> levels;
  double z = origin - step * std::floor((origin - low) / step);
  for (; z <= high + 1e-9; z += step) {
    if (z >= low - 1e-9)
      levels.push_back(z);
  }
  return levels;
}

bool Same(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

bool SameOthers(const Placement& a, const Placement& b, std::size_t active) {
  if (a.size() != b.size())
    return false;
  for (std::size_t u = 0; u < a.size(); ++u) {
    if (u != active && !Same(a[u], b[u]))
      return false;
  }
  return true;
}

}  // namespace

std::unique_ptr<ModelObservations> ModelObservations::For(const Scenario& scenario,
                                                          const Obstacles& buildings) {
  const auto& o = scenario.env.observations;
  if (std::none_of(o.begin(), o.end(), [](const std::string& f) { return IsModelObservation(f); }))
    return nullptr;
  return std::make_unique<ModelObservations>(scenario, buildings);
}

ModelObservations::ModelObservations(const Scenario& scenario, const Obstacles& buildings)
    : scenario_(scenario), buildings_(buildings), bound_(CoverageRewardBound(scenario)) {
  const auto& o = scenario.env.observations;
  coverage_ = std::find(o.begin(), o.end(), "coverage") != o.end();
  lookahead_ = std::find(o.begin(), o.end(), "lookahead") != o.end();
  for (std::size_t a = 0; a < scenario.env.actions.size(); ++a)
    moves_.push_back(MoveDisplacement(scenario, static_cast<int>(a)));
  to_best_ = ToBestAction(scenario);
  pointer_of_.resize(scenario.uavs.size());
  pointer_for_.resize(scenario.uavs.size());
  if (to_best_ >= 0) {
    routes_.reserve(scenario.uavs.size());
    for (std::size_t u = 0; u < scenario.uavs.size(); ++u)
      routes_.emplace_back(scenario, buildings, u);
  }
}

Vec3 ModelObservations::ToBestMove(std::size_t uav, const Placement& placement) {
  return routes_.at(uav).NextMove(pointer_of_.at(uav), placement);
}

const Vec3* ModelObservations::PointerTargetOf(std::size_t uav, const Placement& placement) const {
  const Placement& for_placement = pointer_for_.at(uav);
  const bool current = for_placement.size() == placement.size() &&
                       std::equal(placement.begin(), placement.end(), for_placement.begin(), Same);
  return current ? &pointer_of_[uav] : nullptr;
}

void ModelObservations::Coverage(const Placement& placement, std::size_t active,
                                 AnalyticEvaluator& model, const RewardOf& reward_of,
                                 std::vector<double>& out) {
  if (!coverage_values_.empty() && active == coverage_active_ &&
      SameOthers(placement, coverage_for_, active)) {
    out = coverage_values_;
    pointer_of_[active] = best_point_;
    pointer_for_[active] = placement;
    return;
  }
  const Box& zone = scenario_.uavs[active].zone;
  const Vec3& origin = scenario_.uavs[active].initial;
  const double step = scenario_.env.step;
  const int cells = scenario_.env.coverage_map;
  const std::vector<double> levels = LatticeAltitudes(origin.z, step, zone.zmin, zone.zmax);
  const auto n = static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells);
  std::vector<double> values(2 * n, 0.0);
  Placement probe = placement;
  // The other UAVs stay where they are: their links are worked out once for the whole map.
  std::vector<std::vector<UeLink>> others(placement.size());
  std::vector<const std::vector<UeLink>*> links(placement.size());
  for (std::size_t u = 0; u < placement.size(); ++u) {
    if (u != active) {
      others[u] = model.LinksAt(u, placement[u]);
      links[u] = &others[u];
    }
  }
  if (placement.size() > 1)
    ForgetLinksIfUesMoved(model);  // once per map, not once per point
  OneUavMoves moves(model, placement, active, links);
  double best_of_map = -1.0;
  best_point_ = placement[active];
  for (int row = 0; row < cells; ++row) {
    const double cy = zone.ymin + (row + 0.5) * (zone.ymax - zone.ymin) / cells;
    const double y = NearestOnLattice(cy, origin.y, step, zone.ymin, zone.ymax);
    for (int col = 0; col < cells; ++col) {
      const double cx = zone.xmin + (col + 0.5) * (zone.xmax - zone.xmin) / cells;
      const double x = NearestOnLattice(cx, origin.x, step, zone.xmin, zone.xmax);
      double best = -1.0, best_z = 0.0;
      for (std::size_t level = 0; level < levels.size(); ++level) {
        const double z = levels[level];
        probe[active] = {x, y, z};
        if (buildings_.SolidAt(probe[active]) >= 0)
          continue;
        const std::size_t point =
            static_cast<std::size_t>(row * cells + col) * levels.size() + level;
        // The same numbers as model.Evaluate(probe), which would work out every link again.
        const std::vector<UeLink>& links_here = MapLinks(active, point, probe[active], model);
        moves.ScoreInto(probe[active], links_here, point_info_,
                        placement.size() > 1 ? &map_shares_[active][point] : nullptr);
        const double r = reward_of(point_info_);
        if (r > best) {
          best = r;
          best_z = z;
        }
      }
      const auto cell = static_cast<std::size_t>(row * cells + col);
      if (best > best_of_map) {
        best_of_map = best;
        best_point_ = {x, y, best_z};
      }
      if (best >= 0) {
        values[cell] = std::clamp(best / bound_, 0.0, 1.0);
        values[n + cell] =
            zone.zmax > zone.zmin
                ? std::clamp((best_z - zone.zmin) / (zone.zmax - zone.zmin), 0.0, 1.0)
                : 0.0;
      }
    }
  }
  if (scenario_.env.coverage_refine > 0)
    RefinePointer(levels, best_of_map, moves, active, model, reward_of);
  pointer_of_[active] = best_point_;
  pointer_for_[active] = placement;
  coverage_for_ = placement;
  coverage_active_ = active;
  coverage_values_ = values;
  out = std::move(values);
}

void ModelObservations::RefinePointer(const std::vector<double>& levels, double best_of_map,
                                      OneUavMoves& moves, std::size_t active,
                                      AnalyticEvaluator& model, const RewardOf& reward_of) {
  const Box& zone = scenario_.uavs[active].zone;
  const double step = scenario_.env.step;
  const int radius = scenario_.env.coverage_refine;
  const Vec3 centre = best_point_;
  double best = best_of_map;  // the cell's own column keeps the pointer on a tie
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const double x = centre.x + dx * step;
      const double y = centre.y + dy * step;
      if (x < zone.xmin || x > zone.xmax || y < zone.ymin || y > zone.ymax)
        continue;
      for (const double z : levels) {
        const Vec3 point{x, y, z};
        if (buildings_.SolidAt(point) >= 0)
          continue;
        scratch_links_ = model.LinksAt(active, point);
        moves.ScoreInto(point, scratch_links_, point_info_);
        const double r = reward_of(point_info_);
        if (r > best) {
          best = r;
          best_point_ = point;
        }
      }
    }
  }
}

void ModelObservations::ForgetLinksIfUesMoved(const AnalyticEvaluator& model) {
  const std::vector<Vec3>& ues = model.UePositions();
  if (map_links_.empty() ||
      !std::equal(ues.begin(), ues.end(), map_links_ues_.begin(), map_links_ues_.end(), Same)) {
    map_links_.assign(scenario_.uavs.size(), {});
    map_shares_.assign(scenario_.uavs.size(), {});
    map_links_ues_ = ues;
  }
}

const std::vector<UeLink>& ModelObservations::MapLinks(std::size_t active, std::size_t point,
                                                       const Vec3& position,
                                                       AnalyticEvaluator& model) {
  if (scenario_.uavs.size() == 1) {
    scratch_links_ = model.LinksAt(active, position);
    return scratch_links_;
  }
  std::vector<std::vector<UeLink>>& of_uav = map_links_[active];
  if (of_uav.size() <= point) {
    of_uav.resize(point + 1);
    map_shares_[active].resize(point + 1);
  }
  if (of_uav[point].empty())
    of_uav[point] = model.LinksAt(active, position);
  return of_uav[point];
}

void ModelObservations::AddPointer(const Vec3& from, std::vector<double>& out) const {
  const double step = scenario_.env.step;
  const auto offset = [step](double metres) {
    return std::clamp(metres / step, -kPointerStepLimit, kPointerStepLimit);
  };
  out.push_back(offset(best_point_.x - from.x));
  out.push_back(offset(best_point_.y - from.y));
  out.push_back(offset(best_point_.z - from.z));
}

void ModelObservations::Fill(const Placement& placement, std::size_t active, double here,
                             AnalyticEvaluator& model, const RewardOf& reward_of, StepInfo& info) {
  if (coverage_) {
    Coverage(placement, active, model, reward_of, info.coverage);
    AddPointer(placement[active], info.coverage);
  }
  if (!lookahead_)
    return;
  info.lookahead.assign(moves_.size(), 0.0);
  for (std::size_t a = 0; a < moves_.size(); ++a) {
    const Vec3 move = static_cast<int>(a) == to_best_ ? ToBestMove(active, placement) : moves_[a];
    const Placement to = ApplyDisplacement(scenario_, buildings_, active, move, placement);
    if (Same(to[active], placement[active]))
      continue;
    info.lookahead[a] =
        std::clamp(kLookaheadGain * (reward_of(model.Evaluate(to)) - here) / bound_, -1.0, 1.0);
  }
}

}  // namespace rlpos
