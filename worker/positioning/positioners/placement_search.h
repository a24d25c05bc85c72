#pragma once
// The analytic oracle's search, shared by OracleSearch (decided once) and TrackingOracle
// (decided again every interval as the UEs move): the zone grids, every UE's link at their
// points, and the search over them scored with the analytic model.
#include <cstddef>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/reward.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/positioners/positioners.h"

namespace rlpos {

// Each UAV's zone grid and the UEs' links at its points. Within `budget_bytes` the links are
// tabulated on first use and kept: a search revisits them all, and a run that moves some UEs
// recomputes only theirs (MoveUes). Beyond it, they are computed on each visit.
class ZoneLinkTable {
 public:
  ZoneLinkTable(const Scenario& scenario, double step, std::size_t budget_bytes);

  std::size_t Uavs() const { return grids_.size(); }
  const std::vector<Vec3>& Grid(std::size_t uav) const { return grids_[uav]; }
  // UAV `uav`'s links to every UE at its grid point `g`, by `analytic` (the UEs where it has
  // them). Valid until the next call for the same UAV.
  const std::vector<UeLink>& Links(AnalyticEvaluator& analytic, std::size_t uav, std::size_t g);
  // `analytic`'s UEs moved from `before` to where it has them now: the tabulated links of the
  // UEs that moved are recomputed, the others kept.
  void MoveUes(AnalyticEvaluator& analytic, const std::vector<Vec3>& before);

 private:
  std::vector<std::vector<Vec3>> grids_;
  std::size_t n_ues_;
  bool tabulate_;
  // Per UAV: empty until first used, then per grid point every UE's link.
  std::vector<std::vector<std::vector<UeLink>>> table_;
  std::vector<std::vector<UeLink>> scratch_;  // per UAV, when not tabulated
};

// The analytic part of OracleSearch, best first, on `links` (of `scenario`'s grids) with the UEs
// where `analytic` has them; `scenario`'s UE positions must be the same (the centroid start).
// k UAVs: the searches start from the baseline, the centroid placement, `extra_starts` (each
// UAV at its grid point nearest), then the random starts of `options`.
std::vector<ScoredPlacement> AnalyticOracle(const Scenario& scenario, AnalyticEvaluator& analytic,
                                            ZoneLinkTable& links, const Reward& reward,
                                            const OracleOptions& options,
                                            const std::vector<Placement>& extra_starts = {});

// The grid step OracleSearch uses for `scenario` with `options`.
double OracleGridStep(const Scenario& scenario, const OracleOptions& options);

}  // namespace rlpos
