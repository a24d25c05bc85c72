#include "common/phy/airtime_model.h"

#include <algorithm>
#include <cmath>

#include "common/phy/dcf_contention.h"

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

// The mean backoff of a station alone on the channel, in us: a constant, computed once.
double LoneBackoffUs() {
  static const double us = SaturatedDcf(1, kCwMin, kCwMax).idle_slots_per_success * kSlotUs;
  return us;
}
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
  const double lone_backoff_us = LoneBackoffUs();
  return a.delivered_mbit / phy_rate_mbps * 1e6 / (a.busy_us + lone_backoff_us);
}

namespace {

// Mixes a station's own accesses with the slow ones that follow its captures.
Access Blend(const Access& own, const Access& slow, double slow_share) {
  auto mix = [&](double a, double b) { return (1.0 - slow_share) * a + slow_share * b; };
  return {mix(own.mpdus, slow.mpdus), mix(own.ppdu_us, slow.ppdu_us),
          mix(own.busy_us, slow.busy_us), mix(own.delivered_mbit, slow.delivered_mbit)};
}

}  // namespace

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size,
                                          const CaptureCost& capture) {
  AirtimeEstimate e;
  const std::size_t n = links.size();
  e.throughput_mbps.assign(n, 0.0);
  std::vector<Access> access(n);
  std::vector<double> wanted(n, 0.0);  // accesses per second that would carry the demand
  std::vector<std::size_t> active;     // the stations that contend
  for (std::size_t i = 0; i < n; ++i) {
    access[i] = FullAccess(links[i].phy_rate_mbps, packet_size, links[i].mpdu_success);
    if (access[i].delivered_mbit <= 0 || links[i].demand_mbps <= 0)
      continue;
    wanted[i] = links[i].demand_mbps / access[i].delivered_mbit;
    active.push_back(i);
  }
  if (active.empty())
    return e;
  // Who contends: every active station once the channel is full; at lighter load a station
  // finds the others idle in proportion to the load, so contention grows with it.
  const double lone_backoff_us = LoneBackoffUs();
  double load = 0.0;
  for (std::size_t i : active)
    load += wanted[i] * (access[i].busy_us + lone_backoff_us);
  load *= 1e-6;
  const double contenders = static_cast<double>(active.size());
  e.contenders = 1.0 + (contenders - 1.0) * std::min(1.0, load);
  const DcfContention dcf = SaturatedDcf(e.contenders, kCwMin, kCwMax);
  std::vector<double> weight(n, 1.0);  // accesses relative to an equal share
  if (capture.follow_up_rate_mbps > 0 && active.size() > 1) {
    std::vector<double> snr;
    for (std::size_t i : active)
      snr.push_back(links[i].snr_db);
    const CaptureShares shares = ContendWithCapture(snr, std::min(1.0, load), capture.contention);
    const Access slow = FullAccess(capture.follow_up_rate_mbps, packet_size);
    for (std::size_t k = 0; k < active.size(); ++k) {
      const std::size_t i = active[k];
      weight[i] = shares.access_weight[k];
      access[i] = Blend(access[i], slow, shares.capture_share[k]);
      wanted[i] = links[i].demand_mbps / access[i].delivered_mbit;
    }
  }
  // A collision lasts as long as the longer of the two PPDUs (collisions of three are rare).
  double longer = 0.0;
  for (std::size_t i : active)
    for (std::size_t j : active)
      longer += std::max(access[i].ppdu_us, access[j].ppdu_us);
  longer /= contenders * contenders;
  const double contention_us = dcf.idle_slots_per_success * kSlotUs +
                               dcf.collisions_per_success * (longer + kAccessOverheadUs);
  auto airtime_at = [&](double share) {  // share: accesses per second of an equal-weight station
    double airtime = 0.0;
    for (std::size_t i : active)
      airtime +=
          std::min(wanted[i], share * weight[i]) * (access[i].busy_us + contention_us) * 1e-6;
    return airtime;
  };
  double max_share = 0.0;  // the share at which every demand is met
  for (std::size_t i : active)
    max_share = std::max(max_share, wanted[i] / weight[i]);
  e.airtime_demanded = airtime_at(max_share);
  // Each UE gets min(wanted, weight * A) accesses with A the largest share that fits.
  double share = max_share;
  if (e.airtime_demanded > 1.0) {
    double lo = 0.0, hi = max_share;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      double& end = airtime_at(mid) > 1.0 ? hi : lo;
      if (end == mid)
        break;  // no later step would move either end: the bits of all 100 steps
      end = mid;
    }
    share = lo;
  }
  for (std::size_t i : active) {
    // A met demand is the demand itself, not a round trip through accesses per second.
    e.throughput_mbps[i] = wanted[i] <= share * weight[i]
                               ? links[i].demand_mbps
                               : share * weight[i] * access[i].delivered_mbit;
    e.aggregate_mbps += e.throughput_mbps[i];
  }
  return e;
}

}  // namespace rlpos
