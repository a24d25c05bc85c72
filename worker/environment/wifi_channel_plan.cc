#include "environment/wifi_channel_plan.h"

#include <ns3/wifi-phy-operating-channel.h>
#include <tuple>

#include "config/config_error.h"
#include "metrics/mcs_table.h"

namespace rlpos {

WifiChannelPlan PlanWifiChannel(const WifiSpec& wifi) {
  WifiChannelPlan plan{};
  if (wifi.standard == "802.11n") {
    plan.standard = ns3::WIFI_STANDARD_80211n;
  } else if (wifi.standard == "802.11ac") {
    plan.standard = ns3::WIFI_STANDARD_80211ac;
  } else {
    plan.standard = ns3::WIFI_STANDARD_80211ax;
  }
  // Channels 1-14 are the 2.4 GHz band; the 6 GHz band is not offered (numbers overlap 5 GHz).
  plan.band = wifi.channel <= 14 ? ns3::WIFI_PHY_BAND_2_4GHZ : ns3::WIFI_PHY_BAND_5GHZ;
  if (plan.standard == ns3::WIFI_STANDARD_80211ac && plan.band != ns3::WIFI_PHY_BAND_5GHZ) {
    throw ConfigError("/wifi/channel", "802.11ac operates in the 5 GHz band only (channel >= 36)");
  }
  const auto it = ns3::WifiPhyOperatingChannel::FindFirst(
      static_cast<uint8_t>(wifi.channel), 0, static_cast<uint16_t>(wifi.width_mhz), plan.standard,
      plan.band);
  if (it == ns3::WifiPhyOperatingChannel::m_frequencyChannels.end()) {
    throw ConfigError("/wifi/channel", "channel " + std::to_string(wifi.channel) + " is not a " +
                                           std::to_string(wifi.width_mhz) + " MHz " +
                                           wifi.standard + " channel (e.g. 160 MHz: 50 or 114)");
  }
  plan.center_frequency_hz = std::get<1>(*it) * 1e6;
  const std::string band = plan.band == ns3::WIFI_PHY_BAND_5GHZ ? "BAND_5GHZ" : "BAND_2_4GHZ";
  plan.channel_settings = "{" + std::to_string(wifi.channel) + ", " +
                          std::to_string(wifi.width_mhz) + ", " + band + ", 0}";
  plan.rx_noise_figure_db = wifi.noise_floor_dbm - ThermalNoiseDbm(wifi.width_mhz);
  return plan;
}

}  // namespace rlpos
