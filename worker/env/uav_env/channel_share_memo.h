#pragma once
// The airtime model's aggregate throughput of one channel's UEs, remembered by its exact inputs.
// With several UAVs, each on a channel of its own, a search that moves one UAV (a coverage map's
// columns, coordinate descent's candidates) changes one channel's share at a time: the other
// channels' UEs and links recur, and their shares are looked up instead of solved again (the
// capture fixed point is most of a multi-UAV map's time). Keys are compared bit for bit, so a
// lookup gives the bits of a solve. For one evaluator: its packet size and capture cost are
// fixed, so they are not part of the key.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/phy/airtime_model.h"

namespace rlpos {

class ChannelShareMemo {
 public:
  // Key words (8 bytes each, 4 per UE) kept before the memo starts again empty: 2 MiB of keys,
  // about 6,500 channels of ten UEs. A flight of six UAVs makes six coverage maps a round, each
  // with one new channel state per point at most (one_uav_moves.h): 2 MiB holds two rounds and
  // more (a quarter of it made such flights a third slower). Full, it costs a process about
  // 2.5 MB more than a quarter did: 160 MB for a batch of 64 multi-UAV envs.
  static constexpr std::size_t kMaxKeyWords = 256 * 1024;

  // EstimateAirtimeThroughput(domain, packet_size, capture).aggregate_mbps.
  double Aggregate(const std::vector<AirtimeLink>& domain, int packet_size,
                   const CaptureCost& capture);
  void Clear();
  std::size_t Size() const { return shares_.size(); }
  std::size_t KeyWords() const { return key_words_; }

 private:
  struct KeyHash {
    std::size_t operator()(const std::vector<std::uint64_t>& key) const;
  };
  std::unordered_map<std::vector<std::uint64_t>, double, KeyHash> shares_;
  std::size_t key_words_ = 0;       // in the keys of shares_
  std::vector<std::uint64_t> key_;  // reused between lookups
};

}  // namespace rlpos
