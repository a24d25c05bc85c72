// rlpos-standin-sim: answers a job at once, for benchmarks of the runner alone
// (scripts/bench_dispatch.sh). It takes the command line the worker gives rlpos-sim and prints a
// result the coordinator accepts: the position job gives the scenario's UAV position; the eval
// job echoes its position and the scenario's RngRun with fixed metrics. Train jobs are refused:
// benchmark campaigns use fixed positioners.
//   rlpos-standin-sim position --scenario FILE --positioner NAME --json
//   rlpos-standin-sim eval --scenario FILE --position X,Y,Z --json --no-progress
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/program_usage.h"

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-standin-sim position|eval --scenario FILE ...\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc < 2)
    return rlpos::testing::UsageError(kUsage);
  const std::string kind = argv[1];
  std::string scenario_file, position;
  for (int i = 2; i + 1 < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--scenario")
      scenario_file = argv[++i];
    else if (flag == "--position")
      position = argv[++i];
  }
  std::ifstream in(scenario_file);
  if (!in) {
    std::fprintf(stderr, "rlpos-standin-sim: %s: cannot open file\n", scenario_file.c_str());
    return 2;
  }
  const nlohmann::json scenario = nlohmann::json::parse(in);
  nlohmann::json result;
  if (kind == "position") {
    result["position"] = scenario.at("uav").at("position");
  } else if (kind == "eval") {
    double x = 0, y = 0, z = 0;
    if (std::sscanf(position.c_str(), "%lf,%lf,%lf", &x, &y, &z) != 3) {
      std::fprintf(stderr, "rlpos-standin-sim: --position: expected X,Y,Z\n");
      return 2;
    }
    const int ues = static_cast<int>(scenario.at("ues").size());
    result = {{"position", {x, y, z}},
              {"aggregate_throughput_mbps", 100.0},
              {"mean_delay_ms", 5.0},
              {"loss_ratio", 0.0},
              {"min_snr_db", 20.0},
              {"n_los", ues},
              {"n_ues", ues},
              {"demands_met", ues},
              {"run", scenario.at("simulation").at("run")}};
  } else {
    std::fprintf(stderr, "rlpos-standin-sim: %s jobs are not supported\n", kind.c_str());
    return 2;
  }
  std::printf("%s\n", result.dump().c_str());
  return 0;
}
