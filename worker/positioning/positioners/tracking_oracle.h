#pragma once
// The oracle decided again as the UEs move (oracle-track): each decision is the analytic
// oracle's best placement (OracleSearch without packet-level re-scores) for the UEs where they
// are at that moment. Work is reused across decisions without changing any result: the UEs'
// links at the zone grids are kept (within a budget) and only the UEs that moved get theirs
// recomputed; with several UAVs the previous decision is one more start of the search, so a
// decision is at least as good as a search from the oracle's own starts alone; when no UE moved
// since, the previous decision is the decision.
#include <cstddef>
#include <memory>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

class TrackingOracle {
 public:
  // Links kept up to this many bytes (beyond: computed at each decision, the same numbers).
  static constexpr std::size_t kLinkBudgetBytes = 256u << 20;

  explicit TrackingOracle(const Scenario& scenario,
                          std::size_t link_budget_bytes = kLinkBudgetBytes);
  ~TrackingOracle();
  TrackingOracle(const TrackingOracle&) = delete;
  TrackingOracle& operator=(const TrackingOracle&) = delete;

  // The best placement for the UEs at `ue_positions` (one per UE, in the scenario's order).
  // One UAV: the grid's optimum, as OracleSearch. k UAVs: OracleSearch's coordinate descent from
  // its starts for these UE positions plus the previous decision.
  Placement Decide(const std::vector<Vec3>& ue_positions);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rlpos
