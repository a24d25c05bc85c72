#include "worker/env/uav_env/channel_share_memo.h"

#include "worker/env/uav_env/bit_keys.h"

namespace rlpos {

std::size_t ChannelShareMemo::KeyHash::operator()(const std::vector<std::uint64_t>& key) const {
  std::uint64_t h = 0;
  for (const std::uint64_t word : key)
    h = MixBits(h ^ word);
  return static_cast<std::size_t>(h);
}

double ChannelShareMemo::Aggregate(const std::vector<AirtimeLink>& domain, int packet_size,
                                   const CaptureCost& capture) {
  key_.clear();
  for (const AirtimeLink& link : domain) {
    key_.push_back(DoubleBits(link.demand_mbps));
    key_.push_back(DoubleBits(link.phy_rate_mbps));
    key_.push_back(DoubleBits(link.mpdu_success));
    key_.push_back(DoubleBits(link.snr_db));
  }
  const auto found = shares_.find(key_);
  if (found != shares_.end())
    return found->second;
  const double aggregate = EstimateAirtimeThroughput(domain, packet_size, capture).aggregate_mbps;
  if (key_words_ + key_.size() > kMaxKeyWords)
    Clear();
  shares_.emplace(key_, aggregate);
  key_words_ += key_.size();
  return aggregate;
}

void ChannelShareMemo::Clear() {
  shares_.clear();
  key_words_ = 0;
}

}  // namespace rlpos
