#pragma once
// The scenario's "wifi" section: the 802.11 PHY and MAC every UAV and UE uses, declared once
// (wifi_settings.cc) for the parser, ToJson and the docs.
#include <nlohmann/json.hpp>
#include <string>

#include "common/config/setting.h"

namespace rlpos {

struct WifiSpec {
  std::string standard = "802.11ac";
  int channel = 50;
  int width_mhz = 160;
  int guard_interval_ns = 800;
  int spatial_streams = 1;
  double tx_power_dbm = 20.0;
  double antenna_gain_dbi = 0.0;
  double noise_floor_dbm = -85.0;
  ObjectSpec rate_manager{"ns3::IdealWifiManager", nlohmann::json::object()};
  std::string mode = "ap_sta";
  bool rts_cts = false;
};

const SettingsTable<WifiSpec>& WifiSettings();

}  // namespace rlpos
