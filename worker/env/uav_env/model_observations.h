#pragma once
// The model observations, "coverage" and "lookahead" (worker/env/gym/general_observation.h): what
// the analytic model says of positions the UAV whose turn it is could take, the other UAVs where
// they are. The coverage map is worked out once per placement of the other UAVs (with one UAV, once
// per env) and reused. With several UAVs, each map after another UAV moved re-scores the same
// points: their links to the UEs are kept (while the UEs stand still), and only the association and
// the airtime are worked out again.
#include <cstddef>
#include <functional>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/lattice_route.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/env/uav_env/one_uav_moves.h"

namespace rlpos {

class ModelObservations {
 public:
  using RewardOf = std::function<double(const StepInfo&)>;
  // Null when the scenario's observations need neither field. `buildings`:
  // BuildingObstacles(scenario.buildings) (worker/env/gym/moves.h); both must outlive this.
  static std::unique_ptr<ModelObservations> For(const Scenario& scenario,
                                                const Obstacles& buildings);

  ModelObservations(const Scenario& scenario, const Obstacles& buildings);
  // Fills info.coverage and info.lookahead (those the observations name) for UAV `active` of
  // `placement`, whose reward is `here`.
  void Fill(const Placement& placement, std::size_t active, double here, AnalyticEvaluator& model,
            const RewardOf& reward_of, StepInfo& info);
  // Where the last coverage map's pointer leads: the best cell's column at its best altitude,
  // or what env.coverage_refine found around it.
  const Vec3& PointerTarget() const { return best_point_; }
  // Where UAV `uav`'s coverage map points for `placement` (what the "to_best" move flies
  // towards), or null if its last map was worked out for another placement.
  const Vec3* PointerTargetOf(std::size_t uav, const Placement& placement) const;
  // The "to_best" move of UAV `uav` from `placement`: the first move of a shortest way round the
  // buildings to where its last map points (LatticeRoute). Asks a current PointerTargetOf.
  Vec3 ToBestMove(std::size_t uav, const Placement& placement);

 private:
  void Coverage(const Placement& placement, std::size_t active, AnalyticEvaluator& model,
                const RewardOf& reward_of, std::vector<double>& out);
  // env.coverage_refine: moves best_point_ to the best column within that many moves of it (x
  // and y, every lattice altitude) if one beats the map's best, `best_of_map`.
  void RefinePointer(const std::vector<double>& levels, double best_of_map, OneUavMoves& moves,
                     std::size_t active, AnalyticEvaluator& model, const RewardOf& reward_of);
  // Drops the kept links when the model's UEs are no longer where they were worked out for.
  void ForgetLinksIfUesMoved(const AnalyticEvaluator& model);
  // The UEs' links from map point `point` (its cell and altitude) of UAV `active`'s map, at
  // `position`: kept with several UAVs, worked out each time with one (whose map is made once).
  const std::vector<UeLink>& MapLinks(std::size_t active, std::size_t point, const Vec3& position,
                                      AnalyticEvaluator& model);
  // The offset from `from` to the map's best cell's column at its best altitude.
  void AddPointer(const Vec3& from, std::vector<double>& out) const;

  const Scenario& scenario_;
  const Obstacles& buildings_;
  bool coverage_ = false;
  bool lookahead_ = false;
  double bound_ = 1.0;
  std::vector<Vec3> moves_;  // each action's displacement
  // The last coverage map and what it was worked out for.
  Placement coverage_for_;
  std::size_t coverage_active_ = 0;
  std::vector<double> coverage_values_;
  Vec3 best_point_;                     // the map's best: its column at its best altitude
  std::vector<Vec3> pointer_of_;        // per UAV: best_point_ of its last map
  std::vector<Placement> pointer_for_;  // per UAV: the placement that map was worked out for
  int to_best_ = -1;                    // the index of "to_best" in env.actions, or -1
  std::vector<LatticeRoute> routes_;    // per UAV, with "to_best": its way to its pointer
  // Per UAV, per map point (cell x altitudes + altitude): the UEs' links, empty until asked;
  // and where the UEs were when they were worked out. At most coverage_map² x altitudes x UEs
  // links per UAV (about 40 bytes each).
  std::vector<std::vector<std::vector<UeLink>>> map_links_;
  std::vector<Vec3> map_links_ues_;
  // Per UAV, per map point: its remembered channel shares (one_uav_moves.h), kept and dropped
  // with its links.
  std::vector<std::vector<PointShares>> map_shares_;
  std::vector<UeLink> scratch_links_;
  StepInfo point_info_;  // a map point's state, its vectors reused
};

}  // namespace rlpos
