#include "worker/env/uav_env/placement_memo.h"

#include <algorithm>
#include <new>

#include "worker/env/uav_env/bit_keys.h"

namespace rlpos {

std::uint64_t PlacementHash(const Placement& placement) {
  std::uint64_t h = 0;
  for (const Vec3& p : placement) {
    h = MixBits(h ^ DoubleBits(p.x));
    h = MixBits(h ^ DoubleBits(p.y));
    h = MixBits(h ^ DoubleBits(p.z));
  }
  return h;
}

PlacementMemo::PlacementMemo(std::size_t n_uavs, std::size_t n_ues, std::size_t budget_bytes)
    : n_uavs_(n_uavs),
      n_ues_(n_ues),
      los_words_((n_ues + kLosBitsPerWord - 1) / kLosBitsPerWord),
      stride_(3 * n_uavs + 2 + los_words_ + n_ues * (n_uavs > 1 ? 2 : 1)),
      slots_(budget_bytes / (stride_ * sizeof(double) + 1)) {
  if (slots_ < 4) {  // not one placement fits: no memo
    slots_ = 0;
    return;
  }
  // calloc, not a vector: untouched slots stay unmapped zero pages.
  table_.reset(static_cast<double*>(std::calloc(slots_ * stride_, sizeof(double))));
  if (!table_)
    throw std::bad_alloc();
  filled_.assign(slots_, 0);
}

bool PlacementMemo::Matches(const double* slot, const Placement& placement) const {
  for (std::size_t u = 0; u < n_uavs_; ++u) {
    const Vec3& p = placement[u];
    // Bit for bit: 0.0 and -0.0 are two keys.
    if (DoubleBits(slot[3 * u]) != DoubleBits(p.x) ||
        DoubleBits(slot[3 * u + 1]) != DoubleBits(p.y) ||
        DoubleBits(slot[3 * u + 2]) != DoubleBits(p.z)) {
      return false;
    }
  }
  return true;
}

std::size_t PlacementMemo::Probe(const Placement& placement) const {
  const std::uint64_t h = PlacementHash(placement);
  // Linear probing; the table is never more than three quarters full, so an empty slot ends it.
  std::size_t slot = static_cast<std::size_t>(h % slots_);
  while (filled_[slot] && !Matches(Slot(slot), placement))
    slot = slot + 1 == slots_ ? 0 : slot + 1;
  return slot;
}

bool PlacementMemo::Find(const Placement& placement, StepInfo& info) const {
  if (slots_ == 0 || placement.size() != n_uavs_)
    return false;
  const std::size_t slot = Probe(placement);
  if (!filled_[slot])
    return false;
  const double* v = Slot(slot) + 3 * n_uavs_;
  info.positions = placement;
  info.active_uav = 0;
  info.demands_met = static_cast<int>(v[0]);
  info.throughput_mbps = v[1];
  v += 2;
  info.los.resize(n_ues_);
  info.n_los = 0;  // as the evaluation counts it: the UEs in LoS
  for (std::size_t i = 0; i < n_ues_; ++i) {
    const auto word = static_cast<std::uint64_t>(v[i / kLosBitsPerWord]);
    info.los[i] = static_cast<std::uint8_t>((word >> (i % kLosBitsPerWord)) & 1);
    info.n_los += info.los[i];
  }
  v += los_words_;
  info.snr_db.assign(v, v + n_ues_);
  info.serving.resize(n_ues_);
  for (std::size_t i = 0; i < n_ues_; ++i)
    info.serving[i] = n_uavs_ > 1 ? static_cast<int>(v[n_ues_ + i]) : 0;
  return true;
}

void PlacementMemo::Clear() {
  std::fill(filled_.begin(), filled_.end(), 0);
  size_ = 0;
}

void PlacementMemo::Store(const Placement& placement, const StepInfo& info) {
  if (slots_ == 0 || placement.size() != n_uavs_ || info.snr_db.size() != n_ues_ ||
      info.serving.size() != n_ues_ || info.los.size() != n_ues_) {
    return;
  }
  if (size_ + 1 > Capacity())  // full: start again (the pages stay mapped, no more)
    Clear();
  const std::size_t slot = Probe(placement);
  double* key = Slot(slot);
  for (std::size_t u = 0; u < n_uavs_; ++u) {
    key[3 * u] = placement[u].x;
    key[3 * u + 1] = placement[u].y;
    key[3 * u + 2] = placement[u].z;
  }
  double* v = key + 3 * n_uavs_;
  v[0] = info.demands_met;
  v[1] = info.throughput_mbps;
  v += 2;
  std::vector<std::uint64_t> words(los_words_, 0);
  for (std::size_t i = 0; i < n_ues_; ++i) {
    if (info.los[i])
      words[i / kLosBitsPerWord] |= std::uint64_t{1} << (i % kLosBitsPerWord);
  }
  for (std::size_t w = 0; w < los_words_; ++w)
    v[w] = static_cast<double>(words[w]);  // below 2^52: exact
  v += los_words_;
  std::copy(info.snr_db.begin(), info.snr_db.end(), v);
  if (n_uavs_ > 1) {
    for (std::size_t i = 0; i < n_ues_; ++i)
      v[n_ues_ + i] = info.serving[i];
  }
  if (!filled_[slot]) {
    filled_[slot] = 1;
    ++size_;
  }
}

}  // namespace rlpos
