#include "metrics/airtime_model.h"

#include <algorithm>
#include <cmath>

namespace rlpos {
namespace {
constexpr double kAccessOverheadUs = 34.0 + 67.5 + 40.0 + 16.0 + 52.0;  // DIFS..BlockAck
constexpr double kPerMpduOverheadBytes = 28 + 8 + 20 + 4 + 4;  // MAC, LLC, IP+UDP, delimiter, FCS
constexpr double kMaxAmpduBytes = 65535;
constexpr double kMaxPpduUs = 5484;
constexpr int kBlockAckWindow = 64;
}  // namespace

double MacEfficiency(double phy_rate_mbps, int packet_size) {
  if (phy_rate_mbps <= 0) return 0.0;
  const double mpdu_bytes = packet_size + kPerMpduOverheadBytes;
  const double mpdu_us = mpdu_bytes * 8 / phy_rate_mbps;
  const double n = std::max(1.0, std::min({static_cast<double>(kBlockAckWindow),
                                           std::floor(kMaxAmpduBytes / mpdu_bytes),
                                           std::floor(kMaxPpduUs / mpdu_us)}));
  const double payload_us = n * packet_size * 8 / phy_rate_mbps;
  return payload_us / (n * mpdu_us + kAccessOverheadUs);
}

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size) {
  AirtimeEstimate e;
  e.throughput_mbps.assign(links.size(), 0.0);
  std::vector<double> capacity(links.size(), 0.0);  // Mbit/s if the UE had the channel alone
  double max_demand = 0.0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    capacity[i] = links[i].phy_rate_mbps * MacEfficiency(links[i].phy_rate_mbps, packet_size);
    if (capacity[i] <= 0) continue;
    e.airtime_demanded += links[i].demand_mbps / capacity[i];
    max_demand = std::max(max_demand, links[i].demand_mbps);
  }
  auto airtime_at = [&](double share) {
    double airtime = 0.0;
    for (std::size_t i = 0; i < links.size(); ++i) {
      if (capacity[i] > 0) airtime += std::min(links[i].demand_mbps, share) / capacity[i];
    }
    return airtime;
  };
  // Each UE gets min(demand, T) with T the largest share whose airtime fits in the channel.
  double share = max_demand;
  if (e.airtime_demanded > 1.0) {
    double lo = 0.0, hi = max_demand;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (airtime_at(mid) > 1.0 ? hi : lo) = mid;
    }
    share = lo;
  }
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (capacity[i] > 0) e.throughput_mbps[i] = std::min(links[i].demand_mbps, share);
    e.aggregate_mbps += e.throughput_mbps[i];
  }
  return e;
}

}  // namespace rlpos
