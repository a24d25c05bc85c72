#include "worker/env/network/wifi_channel_plan.h"

#include <ns3/he-phy.h>
#include <ns3/ht-phy.h>
#include <ns3/vht-phy.h>
#include <ns3/wifi-phy-operating-channel.h>

#include <algorithm>
#include <tuple>

#include "common/config/config_error.h"
#include "common/phy/mcs_table.h"

namespace rlpos {

namespace {

WifiChannelPlan PlanChannel(const WifiSpec& wifi, const std::string& path) {
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
    throw ConfigError(path, "802.11ac operates in the 5 GHz band only (channel >= 36)");
  }
  const auto it = ns3::WifiPhyOperatingChannel::FindFirst(static_cast<uint8_t>(wifi.channel), 0,
                                                          static_cast<uint16_t>(wifi.width_mhz),
                                                          plan.standard, plan.band);
  if (it == ns3::WifiPhyOperatingChannel::m_frequencyChannels.end()) {
    throw ConfigError(path, "channel " + std::to_string(wifi.channel) + " is not a " +
                                std::to_string(wifi.width_mhz) + " MHz " + wifi.standard +
                                " channel (e.g. 160 MHz: 50 or 114)");
  }
  plan.channel = wifi.channel;
  plan.center_frequency_hz = std::get<1>(*it) * 1e6;
  const std::string band = plan.band == ns3::WIFI_PHY_BAND_5GHZ ? "BAND_5GHZ" : "BAND_2_4GHZ";
  plan.channel_settings = "{" + std::to_string(wifi.channel) + ", " +
                          std::to_string(wifi.width_mhz) + ", " + band + ", 0}";
  plan.rx_noise_figure_db = wifi.noise_floor_dbm - ThermalNoiseDbm(wifi.width_mhz);
  return plan;
}

// The channel numbers of `width` MHz in the band of `wifi.channel`, ns-3's table order.
std::vector<int> ChannelsOfWidth(const WifiSpec& wifi, ns3::WifiStandard standard,
                                 ns3::WifiPhyBand band) {
  std::vector<int> channels;
  auto it = ns3::WifiPhyOperatingChannel::m_frequencyChannels.begin();
  const auto end = ns3::WifiPhyOperatingChannel::m_frequencyChannels.end();
  while ((it = ns3::WifiPhyOperatingChannel::FindFirst(0, 0, static_cast<uint16_t>(wifi.width_mhz),
                                                       standard, band, it)) != end) {
    const int number = std::get<0>(*it);
    if (std::find(channels.begin(), channels.end(), number) == channels.end())
      channels.push_back(number);
    ++it;
  }
  return channels;
}

}  // namespace

WifiChannelPlan PlanWifiChannel(const WifiSpec& wifi) {
  return PlanChannel(wifi, "/wifi/channel");
}

std::vector<WifiChannelPlan> PlanUavChannels(const Scenario& s) {
  const WifiChannelPlan common = PlanWifiChannel(s.wifi);
  std::vector<int> taken;
  for (const auto& uav : s.uavs) {
    if (uav.channel > 0)
      taken.push_back(uav.channel);
  }
  // 2.4 GHz channels of 20 MHz overlap their neighbours: only 1, 6 and 11 are apart.
  const std::vector<int> band_channels =
      common.band == ns3::WIFI_PHY_BAND_2_4GHZ
          ? (s.wifi.width_mhz == 20 ? std::vector<int>{1, 6, 11} : std::vector<int>{})
          : ChannelsOfWidth(s.wifi, common.standard, common.band);
  std::vector<int> free = {s.wifi.channel};
  for (int c : band_channels) {
    if (c != s.wifi.channel)
      free.push_back(c);
  }
  const std::size_t available = free.size();
  free.erase(std::remove_if(
                 free.begin(), free.end(),
                 [&](int c) { return std::find(taken.begin(), taken.end(), c) != taken.end(); }),
             free.end());
  std::vector<WifiChannelPlan> plans;
  std::size_t next = 0;
  for (std::size_t i = 0; i < s.uavs.size(); ++i) {
    WifiSpec wifi = s.wifi;
    if (s.uavs[i].channel > 0) {
      wifi.channel = s.uavs[i].channel;
    } else if (next < free.size()) {
      wifi.channel = free[next++];
    } else {
      throw ConfigError(s.UavPath(i),
                        std::to_string(s.uavs.size()) + " UAVs need distinct channels but " +
                            s.wifi.standard + " has " + std::to_string(available) +
                            " channels of " + std::to_string(s.wifi.width_mhz) +
                            " MHz in this band; narrow wifi.width or give UAVs the same "
                            "\"channel\" to share the air");
    }
    plans.push_back(PlanChannel(wifi, s.UavPath(i) + "/channel"));
  }
  return plans;
}

ns3::WifiTxVector SingleUserTxVector(const WifiChannelPlan& plan, const WifiSpec& w, int mcs) {
  ns3::WifiMode mode;
  ns3::WifiPreamble preamble;
  if (plan.standard == ns3::WIFI_STANDARD_80211n) {
    mode = ns3::HtPhy::GetHtMcs(static_cast<uint8_t>(mcs + 8 * (w.spatial_streams - 1)));
    preamble = ns3::WIFI_PREAMBLE_HT_MF;
  } else if (plan.standard == ns3::WIFI_STANDARD_80211ac) {
    mode = ns3::VhtPhy::GetVhtMcs(static_cast<uint8_t>(mcs));
    preamble = ns3::WIFI_PREAMBLE_VHT_SU;
  } else {
    mode = ns3::HePhy::GetHeMcs(static_cast<uint8_t>(mcs));
    preamble = ns3::WIFI_PREAMBLE_HE_SU;
  }
  const auto nss = static_cast<uint8_t>(w.spatial_streams);
  return ns3::WifiTxVector(mode, 0, preamble, static_cast<uint16_t>(w.guard_interval_ns), nss, nss,
                           0, static_cast<uint16_t>(w.width_mhz), true);
}

}  // namespace rlpos
