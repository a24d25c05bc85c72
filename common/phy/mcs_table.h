#pragma once
// Single-user PHY rates and minimum SNRs per MCS for HT (802.11n), VHT (802.11ac) and
// HE (802.11ax): used to turn a demand into "the MCS it needs" and that MCS into a minimum SNR.
#include <string>

namespace rlpos {

struct PhyProfile {
  std::string standard = "802.11ac";
  int width_mhz = 160;
  int guard_interval_ns = 800;
  int spatial_streams = 1;
};

// Highest MCS index of the standard (7 for HT per stream, 9 for VHT, 11 for HE).
int MaxMcs(const std::string& standard);

// PHY data rate in Mbit/s. Example: VHT, 160 MHz, GI 800 ns, 1 stream, MCS 0 -> 58.5.
double McsDataRateMbps(const PhyProfile& phy, int mcs);

// Minimum SNR (dB) for the MCS: the receiver sensitivities of IEEE 802.11-2016/2021
// (tables 19-23, 21-25, 27-51, 20 MHz) referred to the noise of a 10 dB noise-figure receiver
// (-91 dBm at 20 MHz). Width-independent because both signal and noise scale with it.
double McsMinSnrDb(int mcs);

// The lowest MCS whose rate covers `demand_mbps`, or -1 when no MCS of this PHY does.
int RequiredMcs(const PhyProfile& phy, double demand_mbps);

// Thermal noise power (dBm) over the channel width at 290 K.
double ThermalNoiseDbm(int width_mhz);

}  // namespace rlpos
