#include <algorithm>
#include <cstdio>
#include <iostream>

#include "common/mobility/mobility_text.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/network/uav_network.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {
namespace {

// One line per mobility setting in use, with the UEs that have it (all static: one line).
void PrintMobility(const Scenario& scenario) {
  std::vector<std::pair<std::string, std::vector<std::string>>> settings;
  for (const auto& ue : scenario.ues) {
    const std::string text = DescribeMobility(ue.mobility);
    auto it = std::find_if(settings.begin(), settings.end(),
                           [&](const auto& setting) { return setting.first == text; });
    if (it == settings.end())
      it = settings.insert(settings.end(), {text, {}});
    it->second.push_back(ue.name);
  }
  for (const auto& [text, names] : settings) {
    std::string who = std::to_string(names.size()) + " UE" + (names.size() == 1 ? "" : "s");
    if (names.size() < scenario.ues.size() && names.size() <= 4) {
      who += " (";
      for (std::size_t i = 0; i < names.size(); ++i)
        who += (i ? ", " : "") + names[i];
      who += ")";
    }
    std::printf("  mobility    %s: %s\n", who.c_str(), text.c_str());
  }
}

// The scenario at its baseline placement: every UE's link and every UAV, as validate reports them.
struct Baseline {
  nlohmann::json ues = nlohmann::json::array();
  nlohmann::json uavs = nlohmann::json::array();
  int n_los = 0;
};

Baseline DescribeBaseline(const Scenario& scenario) {
  // Built, not run: gives the geometric LoS and SNR of every UE at the baseline placement (to
  // the UAV it associates with).
  UavNetwork network(scenario, scenario.InitialPlacement());
  const auto links = network.Links();
  const auto& serving = network.Association();
  const auto channels = network.UavChannels();
  const PhyProfile phy{scenario.wifi.standard, scenario.wifi.width_mhz,
                       scenario.wifi.guard_interval_ns, scenario.wifi.spatial_streams};
  Baseline b;
  for (std::size_t i = 0; i < links.size(); ++i) {
    b.n_los += links[i].los ? 1 : 0;
    const auto demand = CheckDemand(phy, scenario.ues[i].demand_mbps, links[i].snr_db);
    b.ues.push_back({{"name", scenario.ues[i].name},
                     {"los", links[i].los},
                     {"snr_db", links[i].snr_db},
                     {"demand_mbps", scenario.ues[i].demand_mbps},
                     {"required_mcs", demand.required_mcs},
                     {"demand_met", demand.met},
                     {"uav", scenario.uavs[static_cast<std::size_t>(serving[i])].name},
                     {"mobility", DescribeMobility(scenario.ues[i].mobility)}});
  }
  for (std::size_t u = 0; u < scenario.uavs.size(); ++u) {
    const auto& q = scenario.uavs[u].initial;
    b.uavs.push_back(
        {{"name", scenario.uavs[u].name},
         {"position", {q.x, q.y, q.z}},
         {"channel", channels[u]},
         {"ues_served", std::count(serving.begin(), serving.end(), static_cast<int>(u))}});
  }
  return b;
}

std::size_t CountFootprints(const Scenario& scenario) {
  return static_cast<std::size_t>(
      std::count_if(scenario.buildings.begin(), scenario.buildings.end(),
                    [](const BuildingSpec& b) { return b.HasFootprint(); }));
}

void PrintValidateJson(const Scenario& scenario, const Baseline& b) {
  const auto& p = scenario.uavs.front().initial;
  std::cout << nlohmann::json{{"scenario", scenario.name},
                              {"valid", true},
                              {"ues", b.ues.size()},
                              {"buildings", scenario.buildings.size()},
                              {"footprints", CountFootprints(scenario)},
                              {"total_demand_mbps", scenario.TotalDemandMbps()},
                              {"baseline", {p.x, p.y, p.z}},
                              {"n_los_at_baseline", b.n_los},
                              {"links_at_baseline", b.ues},
                              {"uavs", b.uavs},
                              {"effective", ToJson(scenario)}}
                   .dump(2)
            << std::endl;
}

// The scenario's venue, buildings, UEs, Wi-Fi, propagation and mobility.
void PrintScenarioSummary(const CommonOptions& options, const Scenario& scenario) {
  const std::size_t footprints = CountFootprints(scenario);
  std::printf("%s: valid\n", options.scenario_file.c_str());
  std::printf("  scenario    %s\n", scenario.name.c_str());
  std::printf("  venue       %g x %g m, height limit %g m\n", scenario.venue.width,
              scenario.venue.depth, scenario.venue.height);
  if (footprints > 0)
    std::printf("  buildings   %zu (%zu footprints)\n", scenario.buildings.size(), footprints);
  else
    std::printf("  buildings   %zu\n", scenario.buildings.size());
  std::printf("  UEs         %zu, total demand %.1f Mbit/s\n", scenario.ues.size(),
              scenario.TotalDemandMbps());
  std::printf("  Wi-Fi       %s, channel %d, %d MHz, GI %d ns, %s, %s\n",
              scenario.wifi.standard.c_str(), scenario.wifi.channel, scenario.wifi.width_mhz,
              scenario.wifi.guard_interval_ns, scenario.wifi.mode.c_str(),
              scenario.wifi.rate_manager.type.c_str());
  std::printf("  propagation %s\n", scenario.propagation.type.c_str());
  PrintMobility(scenario);
}

void PrintBaseline(const Scenario& scenario, const Baseline& b) {
  const auto& p = scenario.uavs.front().initial;
  const std::size_t n_links = b.ues.size();
  if (b.uavs.size() == 1) {
    std::printf("  baseline    (%g, %g, %g): in LoS %d/%zu\n", p.x, p.y, p.z, b.n_los, n_links);
  } else {
    for (const auto& uav : b.uavs) {
      std::printf("  UAV %-7s (%g, %g, %g), channel %d, serves %d UE(s)\n",
                  uav["name"].get<std::string>().c_str(), uav["position"][0].get<double>(),
                  uav["position"][1].get<double>(), uav["position"][2].get<double>(),
                  uav["channel"].get<int>(), uav["ues_served"].get<int>());
    }
    std::printf("  baseline    in LoS %d/%zu\n", b.n_los, n_links);
  }
  for (const auto& ue : b.ues) {
    std::printf("    %-10s %-5s SNR %6.1f dB, demand %6.1f Mbit/s (MCS %d) %s%s\n",
                ue["name"].get<std::string>().c_str(), ue["los"].get<bool>() ? "LoS" : "NLoS",
                ue["snr_db"].get<double>(), ue["demand_mbps"].get<double>(),
                ue["required_mcs"].get<int>(), ue["demand_met"].get<bool>() ? "met" : "not met",
                b.uavs.size() == 1 ? "" : (", UAV " + ue["uav"].get<std::string>()).c_str());
  }
}

}  // namespace

int RunValidate(const CommonOptions& options, bool json) {
  const Scenario scenario = LoadScenarioFor(options, {});
  const Baseline baseline = DescribeBaseline(scenario);
  if (json) {
    PrintValidateJson(scenario, baseline);
    return 0;
  }
  PrintScenarioSummary(options, scenario);
  PrintBaseline(scenario, baseline);
  return 0;
}

}  // namespace rlpos::sim
