#include "common/scenario/wifi_settings.h"

#include "common/phy/mcs_table.h"

namespace rlpos {
namespace {

// Widths and guard intervals the standards define; the noise floor above the thermal noise.
void CheckWifi(const WifiSpec& w, const ObjectReader& r) {
  if (w.width_mhz != 20 && w.width_mhz != 40 && w.width_mhz != 80 && w.width_mhz != 160)
    throw ConfigError(r.PathOf("width"), "must be 20, 40, 80 or 160 MHz");
  if (w.standard == "802.11n" && w.width_mhz > 40)
    throw ConfigError(r.PathOf("width"), "802.11n supports 20 or 40 MHz");
  const bool he = w.standard == "802.11ax";
  const int gi = w.guard_interval_ns;
  if (he ? (gi != 800 && gi != 1600 && gi != 3200) : (gi != 400 && gi != 800)) {
    throw ConfigError(r.PathOf("guard_interval"),
                      he ? "802.11ax guard interval must be 800, 1600 or 3200 ns"
                         : w.standard + " guard interval must be 400 or 800 ns");
  }
  const double thermal = ThermalNoiseDbm(w.width_mhz);
  if (w.noise_floor_dbm < thermal) {
    throw ConfigError(r.PathOf("noise_floor"), "is below the thermal noise of a " +
                                                   std::to_string(w.width_mhz) + " MHz channel (" +
                                                   std::to_string(thermal).substr(0, 6) + " dBm)");
  }
}

}  // namespace

const SettingsTable<WifiSpec>& WifiSettings() {
  static const SettingsTable<WifiSpec> table{
      "wifi",
      "/wifi",
      "The 802.11 PHY and MAC of every UAV and UE.",
      {{"standard",
        &WifiSpec::standard,
        NoRange(),
        "the PHY",
        "",
        {"802.11n", "802.11ac", "802.11ax"}},
       {"channel", &WifiSpec::channel, Integers(1, 233),
        "channel number of the first UAV, checked against ns-3's channel table"},
       {"width", &WifiSpec::width_mhz, Integers(20, 160),
        "channel width: 20, 40, 80 or 160 (802.11n: 20 or 40)", "MHz"},
       {"guard_interval", &WifiSpec::guard_interval_ns, Integers(400, 3200),
        "HT and VHT: 400 or 800; HE: 800, 1600 or 3200", "ns"},
       {"spatial_streams", &WifiSpec::spatial_streams, Integers(1, 4),
        "antennas and streams of every node"},
       {"tx_power", &WifiSpec::tx_power_dbm, Between(-30, 40), "transmit power of every node",
        "dBm"},
       {"antenna_gain", &WifiSpec::antenna_gain_dbi, Between(-30, 30), "antenna gain of every node",
        "dBi"},
       {"noise_floor", &WifiSpec::noise_floor_dbm, Between(-140, 0),
        "sets ns-3's RxNoiseFigure to the noise floor minus the thermal noise of the width (at "
        "least that noise)",
        "dBm"},
       {"rate_manager", &WifiSpec::rate_manager, NoRange(),
        "any installed ns-3 WifiRemoteStationManager, with its attributes"},
       {"mode",
        &WifiSpec::mode,
        NoRange(),
        "ap_sta: the UAV is the access point; adhoc: every node a peer (docs/scenarios.md, "
        "\"Ad hoc mode\")",
        "",
        {"adhoc", "ap_sta"}},
       {"rts_cts", &WifiSpec::rts_cts, NoRange(), "RTS/CTS before every frame"}},
      CheckWifi};
  return table;
}

}  // namespace rlpos
