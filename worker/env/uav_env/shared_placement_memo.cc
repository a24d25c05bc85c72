#include "worker/env/uav_env/shared_placement_memo.h"

#include <algorithm>

namespace rlpos {

std::size_t SharedPlacementMemo::BudgetFor(std::size_t envs) {
  const std::size_t per_env = PlacementMemo::kDefaultBudgetBytes;
  return envs >= kMaxBudgetBytes / per_env ? kMaxBudgetBytes
                                           : std::max<std::size_t>(envs, 1) * per_env;
}

SharedPlacementMemo::SharedPlacementMemo(std::size_t n_uavs, std::size_t n_ues,
                                         std::size_t budget_bytes) {
  shards_.reserve(kShards);
  for (std::size_t s = 0; s < kShards; ++s)
    shards_.push_back(std::make_unique<Shard>(n_uavs, n_ues, budget_bytes / kShards));
}

SharedPlacementMemo::Shard& SharedPlacementMemo::ShardOf(const Placement& placement) const {
  // The top bits: a shard's PlacementMemo picks its slot from the hash modulo its slot count,
  // which the low bits would leave correlated with the shard (a few slots of each shard used).
  const std::uint64_t h = PlacementHash(placement);
  return *shards_[static_cast<std::size_t>((h >> 40) % kShards)];
}

bool SharedPlacementMemo::Find(const Placement& placement, StepInfo& info) const {
  Shard& shard = ShardOf(placement);
  std::lock_guard<std::mutex> lock(shard.mutex);
  return shard.memo.Find(placement, info);
}

void SharedPlacementMemo::Store(const Placement& placement, const StepInfo& info) {
  Shard& shard = ShardOf(placement);
  std::lock_guard<std::mutex> lock(shard.mutex);
  shard.memo.Store(placement, info);
}

std::size_t SharedPlacementMemo::Capacity() const {
  std::size_t total = 0;
  for (const auto& shard : shards_)
    total += shard->memo.Capacity();  // fixed at construction: no lock needed
  return total;
}

std::size_t SharedPlacementMemo::Size() const {
  std::size_t total = 0;
  for (const auto& shard : shards_) {
    std::lock_guard<std::mutex> lock(shard->mutex);
    total += shard->memo.Size();
  }
  return total;
}

}  // namespace rlpos
