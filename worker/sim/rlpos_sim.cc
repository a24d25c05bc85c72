// rlpos-sim: one experiment on one scenario (the paper's main.py, in C++).
//   rlpos-sim validate FILE
//   rlpos-sim eval --scenario FILE --position x,y,z [--duration S] [--run N] [--json]
// Exit codes: 0 success, 1 runtime failure, 2 bad input (usage, scenario, position),
// 3 ns-3 aborted the simulation.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "config/config_error.h"
#include "environment/uav_network.h"
#include "logging/log.h"
#include "metrics/mcs_table.h"
#include "scenario/scenario_parser.h"
#include "sim/abort_guard.h"
#include "sim/metrics_report.h"
#include "sim/scenario_loading.h"

namespace {

constexpr int kExitRuntime = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNs3Abort = 3;

struct CommonOptions {
  std::string scenario_file;
  std::vector<std::string> overrides;
  std::string log_level;
};

void AddScenarioOverrides(CLI::App* command, CommonOptions& options) {
  command->add_option("--set", options.overrides,
                      "Override a scenario field: path=value (e.g. wifi.mode=adhoc); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--log-level", options.log_level, "error|warning|info|debug")
      ->check(CLI::IsMember({"error", "warning", "info", "debug"}));
}

rlpos::Scenario Load(const CommonOptions& options, std::vector<std::string> extra) {
  std::vector<std::string> overrides = std::move(extra);
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  rlpos::Scenario scenario = rlpos::LoadScenario(options.scenario_file, overrides);
  rlpos::SetLogLevel(rlpos::ParseLogLevel(options.log_level.empty() ? scenario.log_level
                                                                    : options.log_level));
  return scenario;
}

std::chrono::steady_clock::time_point g_started;

void ShowProgress(double now, double end) {
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - g_started).count();
  std::fprintf(stderr, "\rsimulated %.1f / %.1f s (wall %.1f s)%s", now, end, wall,
               now >= end ? "\n" : "");
  std::fflush(stderr);
}

int RunEval(const CommonOptions& options, const std::string& position_text, double duration,
            long long run, bool json, bool progress) {
  std::vector<std::string> extra;
  if (duration > 0) extra.push_back("simulation.duration=" + std::to_string(duration));
  if (run >= 0) extra.push_back("simulation.run=" + std::to_string(run));
  const rlpos::Scenario scenario = Load(options, extra);
  const rlpos::Vec3 position = rlpos::ParsePosition(position_text, "--position");
  rlpos::CheckUavPosition(scenario, position, "--position");
  rlpos::Log(rlpos::LogLevel::kInfo, "evaluating scenario " + scenario.name);
  g_started = std::chrono::steady_clock::now();
  const rlpos::RunMetrics metrics =
      rlpos::EvaluatePosition(scenario, position, progress ? ShowProgress : nullptr);
  if (json) {
    nlohmann::json out = rlpos::ToJson(metrics);
    out["scenario"] = scenario.name;
    std::cout << out.dump(2) << std::endl;
  } else {
    rlpos::PrintMetricsTable(std::cout, scenario, metrics);
  }
  return 0;
}

int RunValidate(const CommonOptions& options, bool json) {
  const rlpos::Scenario scenario = Load(options, {});
  // Built, not run: gives the geometric LoS and SNR of every UE at the baseline position.
  rlpos::UavNetwork network(scenario, scenario.uav.initial);
  const auto links = network.Links();
  const rlpos::PhyProfile phy{scenario.wifi.standard, scenario.wifi.width_mhz,
                              scenario.wifi.guard_interval_ns, scenario.wifi.spatial_streams};
  int n_los = 0;
  nlohmann::json ues = nlohmann::json::array();
  for (std::size_t i = 0; i < links.size(); ++i) {
    n_los += links[i].los ? 1 : 0;
    const auto demand = rlpos::CheckDemand(phy, scenario.ues[i].demand_mbps, links[i].snr_db);
    ues.push_back({{"name", scenario.ues[i].name},
                   {"los", links[i].los},
                   {"snr_db", links[i].snr_db},
                   {"demand_mbps", scenario.ues[i].demand_mbps},
                   {"required_mcs", demand.required_mcs},
                   {"demand_met", demand.met}});
  }
  const auto& p = scenario.uav.initial;
  if (json) {
    std::cout << nlohmann::json{{"scenario", scenario.name},
                                {"valid", true},
                                {"ues", ues.size()},
                                {"buildings", scenario.buildings.size()},
                                {"total_demand_mbps", scenario.TotalDemandMbps()},
                                {"baseline", {p.x, p.y, p.z}},
                                {"n_los_at_baseline", n_los},
                                {"links_at_baseline", ues},
                                {"effective", rlpos::ToJson(scenario)}}
                     .dump(2)
              << std::endl;
    return 0;
  }
  std::printf("%s: valid\n", options.scenario_file.c_str());
  std::printf("  scenario    %s\n", scenario.name.c_str());
  std::printf("  venue       %g x %g m, height limit %g m\n", scenario.venue.width,
              scenario.venue.depth, scenario.venue.height);
  std::printf("  buildings   %zu\n", scenario.buildings.size());
  std::printf("  UEs         %zu, total demand %.1f Mbit/s\n", scenario.ues.size(),
              scenario.TotalDemandMbps());
  std::printf("  Wi-Fi       %s, channel %d, %d MHz, GI %d ns, %s, %s\n",
              scenario.wifi.standard.c_str(), scenario.wifi.channel, scenario.wifi.width_mhz,
              scenario.wifi.guard_interval_ns, scenario.wifi.mode.c_str(),
              scenario.wifi.rate_manager.type.c_str());
  std::printf("  propagation %s\n", scenario.propagation.type.c_str());
  std::printf("  baseline    (%g, %g, %g): nLoS %d/%zu\n", p.x, p.y, p.z, n_los, links.size());
  for (const auto& ue : ues) {
    std::printf("    %-10s %-5s SNR %6.1f dB, demand %6.1f Mbit/s (MCS %d) %s\n",
                ue["name"].get<std::string>().c_str(), ue["los"].get<bool>() ? "LoS" : "NLoS",
                ue["snr_db"].get<double>(), ue["demand_mbps"].get<double>(),
                ue["required_mcs"].get<int>(), ue["demand_met"].get<bool>() ? "met" : "not met");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rlpos::InstallAbortGuard("rlpos-sim", kExitNs3Abort);
  CLI::App app{"rlpos-sim: evaluate UAV positions in ns-3 scenarios"};
  app.require_subcommand(1);
  CommonOptions options;

  auto* validate = app.add_subcommand("validate", "Check a scenario and print a summary");
  validate->add_option("file", options.scenario_file, "Scenario JSON")->required();
  bool validate_json = false;
  validate->add_flag("--json", validate_json, "Print the summary as JSON");
  AddScenarioOverrides(validate, options);

  auto* eval = app.add_subcommand("eval", "Simulate the UAV fixed at a position; print metrics");
  std::string position;
  double duration = -1;
  long long run = -1;
  bool eval_json = false;
  bool progress = isatty(STDERR_FILENO) != 0;
  eval->add_option("--scenario", options.scenario_file, "Scenario JSON")->required();
  eval->add_option("--position", position, "UAV position x,y,z (m)")->required();
  eval->add_option("--duration", duration, "Simulated seconds (overrides simulation.duration)")
      ->check(CLI::PositiveNumber);
  eval->add_option("--run,--RngRun", run, "ns-3 RngRun (overrides simulation.run)")
      ->check(CLI::NonNegativeNumber);
  eval->add_flag("--json", eval_json, "Print the metrics as JSON");
  eval->add_flag("--progress,!--no-progress", progress, "Progress on stderr (default: on a TTY)");
  AddScenarioOverrides(eval, options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (*validate) return RunValidate(options, validate_json);
    return RunEval(options, position, duration, run, eval_json, progress);
  } catch (const rlpos::ConfigError& e) {
    const bool cli = e.path().rfind("--", 0) == 0;
    std::cerr << "rlpos-sim: error: " << (cli ? "" : options.scenario_file + ": ") << e.describe()
              << std::endl;
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rlpos-sim: error: " << e.what() << std::endl;
    return kExitRuntime;
  }
}
