#pragma once
// A bounded memo of the analytic state per placement. The env moves on a lattice (env.step from
// the baseline, clamped to the zone), so an agent revisits the same placements over and over,
// and the analytic state is a pure function of the placement: a revisit can skip the LoS tests,
// the loss models and the airtime model. Keys are compared bit for bit, so a hit returns exactly
// what the evaluation gave.
//
// Bounded: a fixed table of slots within a byte budget, one placement per slot (a newcomer
// replaces the slot's previous placement), so the memory of an env does not grow with the
// number of steps or episodes. The table is zeroed memory that the system maps on first use:
// an env that visits few placements holds few pages.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "worker/gym/env.h"

namespace rlpos {

class PlacementMemo {
 public:
  static constexpr std::size_t kDefaultBudgetBytes = 512 * 1024;

  PlacementMemo(std::size_t n_uavs, std::size_t n_ues,
                std::size_t budget_bytes = kDefaultBudgetBytes);

  // The state stored for `placement`: sets `info` (positions, serving, n_los, throughput_mbps,
  // demands_met, snr_db; active_uav 0) and `ue_throughput`. False, touching neither, if the
  // placement is not stored.
  bool Find(const Placement& placement, StepInfo& info, std::vector<double>& ue_throughput) const;
  // Stores the state at `placement` (as AnalyticEvaluator::Evaluate computed it).
  void Store(const Placement& placement, const StepInfo& info,
             const std::vector<double>& ue_throughput);
  // How many placements it holds at most.
  std::size_t Capacity() const { return slots_; }

 private:
  std::size_t SlotOf(const Placement& placement) const;
  bool Matches(const double* slot, const Placement& placement) const;

  struct Free {
    void operator()(double* p) const { std::free(p); }
  };
  std::size_t n_uavs_;
  std::size_t n_ues_;
  // A slot: the key (x, y, z per UAV), then n_los, demands_met, throughput_mbps, then per UE
  // snr_db and throughput, and with several UAVs the serving UAV.
  std::size_t stride_;
  std::size_t slots_;
  std::unique_ptr<double[], Free> table_;
  std::vector<std::uint8_t> filled_;
};

}  // namespace rlpos
