#pragma once
// The analytic throughput estimate of the "analytic" fidelity: no packets, only each UE's link
// (PHY rate and MPDU error rate) and a share of the channel. 802.11 DCF gives backlogged stations
// equal transmit opportunities, each carrying a full A-MPDU, so when the channel cannot carry
// every demand the accesses are shared fairly (the "performance anomaly": a slow station holds
// the channel longest per access and slows everyone) - water-filling over the channel time each
// access costs. That cost includes the contention of the stations that want the channel at once
// (idle backoff slots and collisions, dcf_contention.h), which is what makes a crowded channel
// carry far less than its PHY rates suggest. With a capture model, stations of unequal SNR share
// the accesses unequally and the strong ones pay for their captures with slow A-MPDUs
// (capture_contention.h).
#include <vector>

#include "common/phy/capture_contention.h"

namespace rlpos {

struct AirtimeLink {
  double demand_mbps = 0.0;
  double phy_rate_mbps = 0.0;  // 0: the link carries nothing
  // Probability that an MPDU sent at this rate arrives (1 - PER at the link's SNR); lost MPDUs
  // are sent again in a later A-MPDU, so they cost airtime without carrying data.
  double mpdu_success = 1.0;
  double snr_db = 0.0;  // at the receiver: who captures whom
};

// What a capture costs: the station's next A-MPDU goes at `follow_up_rate_mbps` (the PHY's
// lowest rate). A rate of 0 leaves capture out and gives every station equal accesses.
struct CaptureCost {
  CaptureParams contention;
  double follow_up_rate_mbps = 0.0;
};

struct AirtimeEstimate {
  std::vector<double> throughput_mbps;
  double aggregate_mbps = 0.0;
  double airtime_demanded = 0.0;  // channel time the demands would need (1 = the whole channel)
  double contenders = 0.0;        // effective number of stations contending for the channel
};

// One channel access of a backlogged station: a full A-MPDU and what it costs.
struct Access {
  double mpdus = 0.0;           // MPDUs in the A-MPDU (Block Ack window, A-MPDU and PPDU limits)
  double ppdu_us = 0.0;         // data PPDU (preamble + A-MPDU)
  double busy_us = 0.0;         // AIFS + PPDU + SIFS + BlockAck: the channel time of a success
  double delivered_mbit = 0.0;  // payload that arrives, after MPDU losses
};

// Bytes of one A-MPDU subframe carrying a `packet_size`-byte UDP payload (headers, delimiter, FCS).
int MpduBytes(int packet_size);

Access FullAccess(double phy_rate_mbps, int packet_size, double mpdu_success = 1.0);

// MAC efficiency of a station alone on the channel at a PHY rate: payload time of a full A-MPDU
// of `packet_size`-byte packets over the access's channel time plus the mean backoff.
double MacEfficiency(double phy_rate_mbps, int packet_size);

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size,
                                          const CaptureCost& capture = {});

}  // namespace rlpos
