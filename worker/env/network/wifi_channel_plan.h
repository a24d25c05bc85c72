#pragma once
// Resolves the scenario's Wi-Fi standard/channel/width into ns-3 terms, and checks them against
// ns-3's own channel table so a bad combination is a ConfigError, not an ns-3 abort.
#include <ns3/wifi-phy-band.h>
#include <ns3/wifi-standards.h>
#include <ns3/wifi-tx-vector.h>

#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

struct WifiChannelPlan {
  ns3::WifiStandard standard;
  ns3::WifiPhyBand band;
  int channel;  // its number
  double center_frequency_hz;
  std::string channel_settings;  // the WifiPhy "ChannelSettings" attribute value
  double rx_noise_figure_db;     // so that thermal noise + figure = the configured noise floor
};

WifiChannelPlan PlanWifiChannel(const WifiSpec& wifi);

// The channel of each UAV: its own "channel", or (unset) the first channel of wifi.width in
// wifi.channel's band that no UAV uses yet, starting with wifi.channel. Throws ConfigError
// naming the UAV when a channel is invalid or the band has no channel left for it.
std::vector<WifiChannelPlan> PlanUavChannels(const Scenario& scenario);

// ns-3.37's default error rate model for HT/VHT/HE: the PHYs' own, and the twin the links'
// MCS thresholds and MPDU success rates are computed with.
constexpr char kErrorRateModel[] = "ns3::TableBasedErrorRateModel";

// A single-user transmission at `mcs` of the configured PHY (standard of `plan`, width, guard
// interval, spatial streams of `wifi`).
ns3::WifiTxVector SingleUserTxVector(const WifiChannelPlan& plan, const WifiSpec& wifi, int mcs);

}  // namespace rlpos
