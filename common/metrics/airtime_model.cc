#include "metrics/airtime_model.h"

#include <algorithm>
#include <cmath>

#include "metrics/dcf_contention.h"

namespace rlpos {
namespace {
// 802.11ac in 5 GHz with ns-3's EDCA parameters for best effort (AIFSN 3, CW 15..1023).
constexpr double kSlotUs = 9.0;
constexpr double kSifsUs = 16.0;
constexpr double kAifsUs = kSifsUs + 3 * kSlotUs;
constexpr double kPreambleUs = 40.0;  // VHT: L-STF..VHT-SIG-B
constexpr double kBlockAckUs = 52.0;  // compressed BlockAck at a legacy basic rate
constexpr int kCwMin = 15, kCwMax = 1023;
constexpr double kPerMpduOverheadBytes = 28 + 8 + 20 + 4 + 4;  // MAC, LLC, IP+UDP, delimiter, FCS
constexpr double kMaxAmpduBytes = 65535;
constexpr double kMaxPpduUs = 5484;
constexpr int kBlockAckWindow = 64;
// Channel time of an access besides the data: a collision costs the same (the colliders wait
// for a BlockAck timeout of about a BlockAck's length, the others defer as long).
constexpr double kAccessOverheadUs = kAifsUs + kPreambleUs + kSifsUs + kBlockAckUs;
}  // namespace

int MpduBytes(int packet_size) {
  return packet_size + static_cast<int>(kPerMpduOverheadBytes);
}

Access FullAccess(double phy_rate_mbps, int packet_size, double mpdu_success) {
  Access a;
  if (phy_rate_mbps <= 0)
    return a;
  const double mpdu_bytes = MpduBytes(packet_size);
  const double mpdu_us = mpdu_bytes * 8 / phy_rate_mbps;
  a.mpdus = std::max(
      1.0, std::min({static_cast<double>(kBlockAckWindow), std::floor(kMaxAmpduBytes / mpdu_bytes),
                     std::floor(kMaxPpduUs / mpdu_us)}));
  a.ppdu_us = kPreambleUs + a.mpdus * mpdu_us;
  a.busy_us = a.ppdu_us + kAifsUs + kSifsUs + kBlockAckUs;
  a.delivered_mbit = a.mpdus * packet_size * 8e-6 * std::clamp(mpdu_success, 0.0, 1.0);
  return a;
}

double MacEfficiency(double phy_rate_mbps, int packet_size) {
  if (phy_rate_mbps <= 0)
    return 0.0;
  const Access a = FullAccess(phy_rate_mbps, packet_size);
  const double lone_backoff_us = SaturatedDcf(1, kCwMin, kCwMax).idle_slots_per_success * kSlotUs;
  return a.delivered_mbit / phy_rate_mbps * 1e6 / (a.busy_us + lone_backoff_us);
}

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size) {
  AirtimeEstimate e;
  const std::size_t n = links.size();
  e.throughput_mbps.assign(n, 0.0);
  std::vector<Access> access(n);
  std::vector<double> wanted(n, 0.0);  // accesses per second that would carry the demand
  std::vector<double> ppdus;           // of the stations that contend
  for (std::size_t i = 0; i < n; ++i) {
    access[i] = FullAccess(links[i].phy_rate_mbps, packet_size, links[i].mpdu_success);
    if (access[i].delivered_mbit <= 0 || links[i].demand_mbps <= 0)
      continue;
    wanted[i] = links[i].demand_mbps / access[i].delivered_mbit;
    ppdus.push_back(access[i].ppdu_us);
  }
  if (ppdus.empty())
    return e;
  // Who contends: every active station once the channel is full; at lighter load a station
  // finds the others idle in proportion to the load, so contention grows with it.
  const double lone_backoff_us = SaturatedDcf(1, kCwMin, kCwMax).idle_slots_per_success * kSlotUs;
  double load = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    load += wanted[i] * (access[i].busy_us + lone_backoff_us);
  load *= 1e-6;
  const double active = static_cast<double>(ppdus.size());
  e.contenders = 1.0 + (active - 1.0) * std::min(1.0, load);
  const DcfContention dcf = SaturatedDcf(e.contenders, kCwMin, kCwMax);
  // A collision lasts as long as the longer of the two PPDUs (collisions of three are rare).
  double longer = 0.0;
  for (double a : ppdus)
    for (double b : ppdus)
      longer += std::max(a, b);
  longer /= active * active;
  const double contention_us = dcf.idle_slots_per_success * kSlotUs +
                               dcf.collisions_per_success * (longer + kAccessOverheadUs);
  auto airtime_at = [&](double share) {  // share: accesses per second per station
    double airtime = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      airtime += std::min(wanted[i], share) * (access[i].busy_us + contention_us) * 1e-6;
    }
    return airtime;
  };
  const double max_wanted = *std::max_element(wanted.begin(), wanted.end());
  e.airtime_demanded = airtime_at(max_wanted);
  // Each UE gets min(wanted, A) accesses with A the largest share that fits in the channel.
  double share = max_wanted;
  if (e.airtime_demanded > 1.0) {
    double lo = 0.0, hi = max_wanted;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (airtime_at(mid) > 1.0 ? hi : lo) = mid;
    }
    share = lo;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (wanted[i] <= 0)
      continue;
    // A met demand is the demand itself, not a round trip through accesses per second.
    e.throughput_mbps[i] =
        wanted[i] <= share ? links[i].demand_mbps : share * access[i].delivered_mbit;
    e.aggregate_mbps += e.throughput_mbps[i];
  }
  return e;
}

}  // namespace rlpos
