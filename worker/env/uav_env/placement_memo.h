#pragma once
// A bounded memo of the analytic state per placement. The env moves on a lattice (env.step from
// the baseline, clamped to the zone), so an agent revisits the same placements over and over,
// and the analytic state is a pure function of the placement: a revisit can skip the LoS tests,
// the loss models and the airtime model. Keys are compared bit for bit, so a hit returns exactly
// what the evaluation gave.
//
// Bounded: a fixed hash table within a byte budget (open addressing). When it is three quarters
// full it starts again empty, so the memory of an env does not grow with the number of steps or
// episodes, and a lattice that fits (B's 5,292 points) stays in it for good. The table is zeroed
// memory that the system maps on first use: an env that visits few placements holds few pages.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "worker/env/gym/env.h"

namespace rlpos {

// The hash a memo files `placement` under (every bit of every coordinate counts).
std::uint64_t PlacementHash(const Placement& placement);

class PlacementMemo {
 public:
  // On scenario B (one UAV, 4 UEs): 8,192 slots of 80 bytes, so 6,144 placements.
  static constexpr std::size_t kDefaultBudgetBytes = 640 * 1024;

  PlacementMemo(std::size_t n_uavs, std::size_t n_ues,
                std::size_t budget_bytes = kDefaultBudgetBytes);

  // The state stored for `placement`: sets `info`'s positions, serving, n_los, los,
  // throughput_mbps, demands_met and snr_db, and active_uav to 0. False, leaving `info` as it was,
  // if the placement is not stored.
  bool Find(const Placement& placement, StepInfo& info) const;
  // Stores the state at `placement` (as AnalyticEvaluator::Evaluate computed it).
  void Store(const Placement& placement, const StepInfo& info);
  // Forgets every placement (the states it holds no longer hold, e.g. the UEs moved).
  void Clear();
  // How many placements it holds at most, and how many it holds now.
  std::size_t Capacity() const { return slots_ * 3 / 4; }
  std::size_t Size() const { return size_; }

 private:
  // The slot that holds `placement`, or the empty slot where it would go.
  std::size_t Probe(const Placement& placement) const;
  double* Slot(std::size_t slot) const { return table_.get() + slot * stride_; }
  bool Matches(const double* slot, const Placement& placement) const;

  struct Free {
    void operator()(double* p) const { std::free(p); }
  };
  std::size_t n_uavs_;
  std::size_t n_ues_;
  // A slot: the key (x, y, z per UAV), then demands_met, throughput_mbps, the UEs' LoS flags as
  // bits of whole numbers (n_los is their count), then per UE the SNR, and with several UAVs the
  // serving UAV.
  static constexpr std::size_t kLosBitsPerWord = 52;
  std::size_t los_words_;
  std::size_t stride_;
  std::size_t slots_;
  std::size_t size_ = 0;
  std::unique_ptr<double[], Free> table_;
  std::vector<std::uint8_t> filled_;
};

}  // namespace rlpos
