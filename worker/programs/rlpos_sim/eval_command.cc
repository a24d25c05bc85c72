#include <chrono>
#include <cstdio>
#include <iostream>

#include "common/logging/log.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/programs/rlpos_sim/commands.h"
#include "worker/programs/rlpos_sim/metrics_report.h"

namespace rlpos::sim {
namespace {

std::chrono::steady_clock::time_point g_started;

void ShowProgress(double now, double end) {
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - g_started).count();
  std::fprintf(stderr, "\rsimulated %.1f / %.1f s (wall %.1f s)%s", now, end, wall,
               now >= end ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace

int RunEval(const CommonOptions& options, const EvalOptions& eval) {
  std::vector<std::string> extra;
  if (eval.duration)
    extra.push_back("simulation.duration=" + std::to_string(*eval.duration));
  if (eval.run)
    extra.push_back("simulation.run=" + std::to_string(*eval.run));
  const Scenario scenario = LoadScenarioFor(options, extra);
  const Placement placement = ParsePlacement(scenario, eval.positions, "--position");
  Log(LogLevel::kInfo, "evaluating scenario " + scenario.name);
  g_started = std::chrono::steady_clock::now();
  RunMetrics metrics =
      EvaluatePosition(scenario, placement, eval.progress ? ShowProgress : nullptr);
  // After the packets, not before: the packet-level run is the same as without it. Where the
  // analytic model refuses the scenario's loss model (HybridBuildings reads ns-3's building
  // list) the reward is null, said in one line: the packet metrics stand.
  std::string why;
  metrics.reward = PacketEvalReward(scenario, placement, why);
  if (!why.empty())
    Log(LogLevel::kWarning, "reward: null, the analytic model refuses this scenario: " + why);
  if (eval.json) {
    nlohmann::json out = ToJson(metrics);
    out["scenario"] = scenario.name;
    std::cout << out.dump(2) << std::endl;
  } else {
    PrintMetricsTable(std::cout, scenario, metrics);
  }
  return 0;
}

}  // namespace rlpos::sim
