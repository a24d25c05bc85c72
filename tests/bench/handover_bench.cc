// What the radios a handover needs cost at packet level: the same scenario, placement and run
// built without handover (a radio per UE) and with it (a radio per UE and UAV), alternating,
// `rounds` times each; prints the wall time per simulated second both ways and their ratio,
// and the throughput each gives. Asserts nothing.
//   rlpos-bench-handover SCENARIO.json [DURATION_S] [ROUNDS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "tests/bench/bench_scenario.h"
#include "tests/support/program_usage.h"
#include "worker/env/network/uav_network.h"

namespace {

struct Run {
  double wall_per_simulated_s;
  double throughput_mbps;
};

Run Measure(const rlpos::Scenario& s, rlpos::Handover handover) {
  const auto started = std::chrono::steady_clock::now();
  rlpos::UavNetwork network(s, s.InitialPlacement(), handover);
  network.BeginMeasurement({s.simulation.warmup, s.simulation.duration});
  network.RunUntil(s.simulation.duration);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return {wall / s.simulation.duration, network.Measure().aggregate_throughput_mbps};
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-bench-handover SCENARIO.json [DURATION_S] [ROUNDS]\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 2 || argc > 4)
    return rlpos::testing::UsageError(kUsage);
  const std::optional<rlpos::Scenario> scenario =
      LoadBenchScenario(argv[1], argc > 2 ? argv[2] : nullptr);
  if (!scenario)
    return 1;
  int rounds = 3;
  if (argc > 3) {
    try {
      rounds = std::stoi(argv[3]);
    } catch (const std::exception&) {
      rounds = 0;
    }
    if (rounds < 1) {
      std::fprintf(stderr, "error: rounds: expected a positive integer, got \"%s\"\n", argv[3]);
      return 1;
    }
  }
  try {
    std::vector<double> off, on;
    Run last_off{}, last_on{};
    for (int r = 0; r < rounds; ++r) {
      last_off = Measure(*scenario, rlpos::Handover::kOff);
      last_on = Measure(*scenario, rlpos::Handover::kOn);
      off.push_back(last_off.wall_per_simulated_s);
      on.push_back(last_on.wall_per_simulated_s);
    }
    const double a = Median(off), b = Median(on);
    std::printf("%s, %zu UAVs, %zu UEs, %g s simulated, median of %d rounds:\n",
                scenario->name.c_str(), scenario->uavs.size(), scenario->ues.size(),
                scenario->simulation.duration, rounds);
    std::printf("  without handover: %.3f s per simulated s, %.1f Mbit/s\n", a,
                last_off.throughput_mbps);
    std::printf("  with handover:    %.3f s per simulated s, %.1f Mbit/s (%.2fx)\n", b,
                last_on.throughput_mbps, b / a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
