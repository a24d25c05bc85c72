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

// The stations with a demand and a link that carries it, and what their accesses cost.
struct Stations {
  std::vector<Access> access;
  std::vector<double> wanted;       // accesses per second that would carry the demand
  std::vector<double> weight;       // accesses relative to an equal share
  std::vector<std::size_t> active;  // the stations that contend
  double contention_us = 0.0;       // channel time each access spends winning the channel
};

Stations ActiveStations(const std::vector<AirtimeLink>& links, int packet_size) {
  const std::size_t n = links.size();
  Stations s;
  s.access.resize(n);
  s.wanted.assign(n, 0.0);
  s.weight.assign(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    s.access[i] = FullAccess(links[i].phy_rate_mbps, packet_size, links[i].mpdu_success);
    if (s.access[i].delivered_mbit <= 0 || links[i].demand_mbps <= 0)
      continue;
    s.wanted[i] = links[i].demand_mbps / s.access[i].delivered_mbit;
    s.active.push_back(i);
  }
  return s;
}

// The share of the channel the demands would keep busy, with a lone station's backoff.
double ChannelLoad(const Stations& s) {
  const double lone_backoff_us = LoneBackoffUs();
  double load = 0.0;
  for (std::size_t i : s.active)
    load += s.wanted[i] * (s.access[i].busy_us + lone_backoff_us);
  load *= 1e-6;
  return load;
}

// Stations with a better SNR win more accesses, and the slow follow-up of a capture shares
// the accesses of the station that captured.
void ApplyCapture(Stations& s, const std::vector<AirtimeLink>& links, int packet_size,
                  const CaptureCost& capture, double load) {
  std::vector<double> snr;
  for (std::size_t i : s.active)
    snr.push_back(links[i].snr_db);
  const CaptureShares shares = ContendWithCapture(snr, std::min(1.0, load), capture.contention);
  const Access slow = FullAccess(capture.follow_up_rate_mbps, packet_size);
  for (std::size_t k = 0; k < s.active.size(); ++k) {
    const std::size_t i = s.active[k];
    s.weight[i] = shares.access_weight[k];
    s.access[i] = Blend(s.access[i], slow, shares.capture_share[k]);
    s.wanted[i] = links[i].demand_mbps / s.access[i].delivered_mbit;
  }
}

// A collision lasts as long as the longer of the two PPDUs (collisions of three are rare).
double CollisionPpduUs(const Stations& s) {
  const double contenders = static_cast<double>(s.active.size());
  double longer = 0.0;
  for (std::size_t i : s.active)
    for (std::size_t j : s.active)
      longer += std::max(s.access[i].ppdu_us, s.access[j].ppdu_us);
  longer /= contenders * contenders;
  return longer;
}

// share: accesses per second of an equal-weight station.
double AirtimeAt(const Stations& s, double share) {
  double airtime = 0.0;
  for (std::size_t i : s.active)
    airtime +=
        std::min(s.wanted[i], share * s.weight[i]) * (s.access[i].busy_us + s.contention_us) * 1e-6;
  return airtime;
}

// The largest share below max_share whose airtime fits in the channel, by bisection.
double FittingShare(const Stations& s, double max_share) {
  double lo = 0.0, hi = max_share;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    double& end = AirtimeAt(s, mid) > 1.0 ? hi : lo;
    if (end == mid)
      break;  // no later step would move either end: the bits of all 100 steps
    end = mid;
  }
  return lo;
}

}  // namespace

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size,
                                          const CaptureCost& capture) {
  AirtimeEstimate e;
  e.throughput_mbps.assign(links.size(), 0.0);
  Stations s = ActiveStations(links, packet_size);
  if (s.active.empty())
    return e;
  // Who contends: every active station once the channel is full; at lighter load a station
  // finds the others idle in proportion to the load, so contention grows with it.
  const double load = ChannelLoad(s);
  const double contenders = static_cast<double>(s.active.size());
  e.contenders = 1.0 + (contenders - 1.0) * std::min(1.0, load);
  const DcfContention dcf = SaturatedDcf(e.contenders, kCwMin, kCwMax);
  if (capture.follow_up_rate_mbps > 0 && s.active.size() > 1)
    ApplyCapture(s, links, packet_size, capture, load);
  s.contention_us = dcf.idle_slots_per_success * kSlotUs +
                    dcf.collisions_per_success * (CollisionPpduUs(s) + kAccessOverheadUs);
  double max_share = 0.0;  // the share at which every demand is met
  for (std::size_t i : s.active)
    max_share = std::max(max_share, s.wanted[i] / s.weight[i]);
  e.airtime_demanded = AirtimeAt(s, max_share);
  // Each UE gets min(wanted, weight * A) accesses with A the largest share that fits.
  const double share = e.airtime_demanded > 1.0 ? FittingShare(s, max_share) : max_share;
  for (std::size_t i : s.active) {
    // A met demand is the demand itself, not a round trip through accesses per second.
    e.throughput_mbps[i] = s.wanted[i] <= share * s.weight[i]
                               ? links[i].demand_mbps
                               : share * s.weight[i] * s.access[i].delivered_mbit;
    e.aggregate_mbps += e.throughput_mbps[i];
  }
  return e;
}

}  // namespace rlpos
