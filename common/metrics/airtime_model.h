#pragma once
// The analytic throughput estimate of the "analytic" fidelity: no packets, only the PHY rate of
// each UE's link and a share of airtime. 802.11 DCF gives stations equal transmit opportunities,
// so when the channel cannot carry every demand, throughput is shared fairly (the "performance
// anomaly": a slow station slows everyone) - water-filling over the airtime each bit costs.
#include <vector>

namespace rlpos {

struct AirtimeLink {
  double demand_mbps = 0.0;
  double phy_rate_mbps = 0.0;  // 0: the link carries nothing
};

struct AirtimeEstimate {
  std::vector<double> throughput_mbps;
  double aggregate_mbps = 0.0;
  double airtime_demanded = 0.0;  // airtime the demands would need (1 = the whole channel)
};

// MAC efficiency at a PHY rate: payload time of a full A-MPDU of `packet_size`-byte packets over
// that plus the per-access overhead (DIFS, mean backoff, preamble, SIFS, BlockAck).
double MacEfficiency(double phy_rate_mbps, int packet_size);

AirtimeEstimate EstimateAirtimeThroughput(const std::vector<AirtimeLink>& links, int packet_size);

}  // namespace rlpos
