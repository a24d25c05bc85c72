#pragma once
// One placement memo (placement_memo.h) for the envs of one scenario stepped together on several
// threads (the batched env): a placement one env has evaluated is a hit for every other, so N
// envs warm one table instead of N, and hold one table's memory instead of N.
//
// Thread-safe: the table is split in shards picked by the placement's hash, each a PlacementMemo
// behind its own mutex; a lookup copies the state out under the lock. A hit returns exactly what
// the evaluation gave, whichever env or thread stored it, so results do not depend on the number
// of threads or on which env visited first. Bounded: the shards share the budget, and each
// starts again empty when full, as one PlacementMemo does.
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "worker/env/gym/env.h"
#include "worker/env/uav_env/placement_memo.h"

namespace rlpos {

class SharedPlacementMemo {
 public:
  // Enough for B's whole lattice (5,292 placements) several times over, and for a large part of
  // a 12-UE urban lattice; pages the envs never reach stay unmapped.
  static constexpr std::size_t kMaxBudgetBytes = 4 * 1024 * 1024;
  // Far more than the threads of a batch (the cores), so two rarely wait for one shard.
  static constexpr std::size_t kShards = 16;

  // The budget a batch of `envs` envs of one scenario gets: one env's own memo's each, at most
  // kMaxBudgetBytes (so N = 1 holds what a single env holds, and N = 256 a few KiB per env).
  static std::size_t BudgetFor(std::size_t envs);

  SharedPlacementMemo(std::size_t n_uavs, std::size_t n_ues, std::size_t budget_bytes);

  // As PlacementMemo's, callable from any thread.
  bool Find(const Placement& placement, StepInfo& info) const;
  void Store(const Placement& placement, const StepInfo& info);
  // How many placements it holds at most, and now (a snapshot while others store).
  std::size_t Capacity() const;
  std::size_t Size() const;

 private:
  struct Shard {
    Shard(std::size_t n_uavs, std::size_t n_ues, std::size_t budget_bytes)
        : memo(n_uavs, n_ues, budget_bytes) {}
    mutable std::mutex mutex;
    PlacementMemo memo;
  };
  Shard& ShardOf(const Placement& placement) const;

  std::vector<std::unique_ptr<Shard>> shards_;
};

}  // namespace rlpos
