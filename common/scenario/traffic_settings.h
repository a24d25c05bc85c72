#pragma once
// The scenario's "traffic" (the UEs' uplink) and "simulation" (time and seeds) sections, declared
// once (traffic_settings.cc) for the parser, ToJson and the docs.
#include <cstdint>
#include <string>

#include "common/config/setting.h"

namespace rlpos {

struct TrafficSpec {
  std::string protocol = "udp_cbr";
  int packet_size = 1400;
};

struct SimulationSpec {
  double duration = 10.0;
  double warmup = 1.0;
  std::uint32_t seed = 1;
  std::uint64_t run = 1;
};

const SettingsTable<TrafficSpec>& TrafficSettings();
const SettingsTable<SimulationSpec>& SimulationSettings();

}  // namespace rlpos
