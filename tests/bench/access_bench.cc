// Who gets the channel at one UAV position: each UE's A-MPDUs over the measurement window,
// counted from ns-3's PhyTxPsduBegin trace, and the MCS they went at. This is how the capture
// behind the analytic model's capture term shows (docs/env.md): strong UEs send more A-MPDUs,
// and some of them at MCS 0.
//   rlpos-bench-access SCENARIO.json X,Y,Z [DURATION_S]
#include <ns3/core-module.h>
#include <ns3/network-module.h>
#include <ns3/wifi-module.h>

#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/config/config_error.h"
#include "tests/bench/bench_scenario.h"
#include "tests/support/program_usage.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/network/uav_network.h"

namespace {

struct UeAccesses {
  long ampdus = 0;
  long mpdus = 0;
  std::map<int, long> by_mcs;
};

std::vector<UeAccesses> g_ues;
double g_window_start = 0.0;

// UavNetwork creates the UEs first, so UE i is node i and the UAV is node N.
std::size_t NodeOf(const std::string& context) {
  return std::stoul(context.substr(context.find("/NodeList/") + 10));
}

void OnPsdu(std::string context, ns3::WifiConstPsduMap psdus, ns3::WifiTxVector tx, double) {
  const std::size_t node = NodeOf(context);
  const auto& psdu = psdus.begin()->second;
  if (node >= g_ues.size() || ns3::Simulator::Now().GetSeconds() < g_window_start ||
      !psdu->GetHeader(0).IsQosData()) {
    return;
  }
  UeAccesses& ue = g_ues[node];
  ++ue.ampdus;
  ue.mpdus += static_cast<long>(psdu->GetNMpdus());
  ++ue.by_mcs[tx.GetMode().GetMcsValue()];
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-bench-access SCENARIO.json X,Y,Z [DURATION_S]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 3 || argc > 4)
    return rlpos::testing::UsageError(kUsage);
  rlpos::Vec3 position;
  try {
    position = rlpos::ParsePosition(argv[2], "position");
  } catch (const rlpos::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.describe().c_str());
    return 1;
  }
  const std::optional<rlpos::Scenario> scenario =
      LoadBenchScenario(argv[1], argc > 3 ? argv[3] : nullptr);
  if (!scenario)
    return 1;
  const rlpos::Scenario& s = *scenario;
  try {
    rlpos::UavNetwork network(s, {position});
    if (ns3::NodeList::GetNNodes() != s.ues.size() + 1) {
      std::fprintf(stderr, "error: expected %zu nodes (the UEs and the UAV), found %u\n",
                   s.ues.size() + 1, ns3::NodeList::GetNNodes());
      return 1;
    }
    g_ues.assign(s.ues.size(), {});
    g_window_start = s.simulation.warmup;
    ns3::Config::Connect("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Phy/PhyTxPsduBegin",
                         ns3::MakeCallback(&OnPsdu));
    network.BeginMeasurement({s.simulation.warmup, s.simulation.duration});
    network.RunUntil(s.simulation.duration);
    const rlpos::RunMetrics m = network.Measure();
    const double seconds = s.simulation.duration - s.simulation.warmup;
    std::printf("%s at (%g, %g, %g), %.1f s: aggregate %.1f Mbit/s\n", s.name.c_str(), position.x,
                position.y, position.z, seconds, m.aggregate_throughput_mbps);
    std::printf("%-8s %7s %8s %10s %10s %7s  %s\n", "ue", "snr_dB", "Mbit/s", "A-MPDU/s",
                "MPDU/A-MPDU", "%MCS0", "A-MPDUs by MCS");
    for (std::size_t i = 0; i < g_ues.size(); ++i) {
      const UeAccesses& ue = g_ues[i];
      const long at_mcs0 = ue.by_mcs.count(0) ? ue.by_mcs.at(0) : 0;
      std::printf("%-8s %7.1f %8.1f %10.1f %10.1f %7.1f ", s.ues[i].name.c_str(), m.ues[i].snr_db,
                  m.ues[i].throughput_mbps, ue.ampdus / seconds,
                  ue.ampdus ? static_cast<double>(ue.mpdus) / ue.ampdus : 0.0,
                  ue.ampdus ? 100.0 * at_mcs0 / ue.ampdus : 0.0);
      for (const auto& [mcs, count] : ue.by_mcs)
        std::printf(" %d:%ld", mcs, count);
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
