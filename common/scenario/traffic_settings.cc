#include "common/scenario/traffic_settings.h"

namespace rlpos {

const SettingsTable<TrafficSpec>& TrafficSettings() {
  static const SettingsTable<TrafficSpec> table{
      "traffic",
      "/traffic",
      "Each UE's uplink to the sink on its UAV.",
      {{"protocol",
        &TrafficSpec::protocol,
        NoRange(),
        "udp_cbr: ns-3's OnOff at the UE's demand; tcp_bulk: BulkSend, saturating",
        "",
        {"udp_cbr", "tcp_bulk"}},
       {"packet_size", &TrafficSpec::packet_size, Integers(64, 65000),
        "application bytes per packet", "B"}}};
  return table;
}

const SettingsTable<SimulationSpec>& SimulationSettings() {
  static const SettingsTable<SimulationSpec> table{
      "simulation",
      "/simulation",
      "Simulated time and ns-3's random streams.",
      {{"duration", &SimulationSpec::duration, Positive(), "simulated time, traffic included", "s"},
       {"warmup", &SimulationSpec::warmup, NonNegative(),
        "excluded from the metrics (association, ARP): they cover [warmup, duration]", "s"},
       {"seed", &SimulationSpec::seed, Integers(1, 4294967295LL), "ns-3's RngSeedManager seed"},
       {"run", &SimulationSpec::run, Integers(0, 9007199254740991LL),
        "ns-3's RngRun: the stream of every random draw"}},
      [](const SimulationSpec& s, const ObjectReader& r) {
        if (s.warmup >= s.duration)
          throw ConfigError(r.PathOf("warmup"), "must be shorter than the duration");
      }};
  return table;
}

}  // namespace rlpos
