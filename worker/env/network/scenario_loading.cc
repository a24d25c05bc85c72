#include "worker/env/network/scenario_loading.h"

#include <ns3/propagation-loss-model.h>
#include <ns3/wifi-remote-station-manager.h>

#include <sstream>

#include "common/config/config_error.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/venue_obstacles.h"
#include "worker/env/network/wifi_channel_plan.h"

namespace rlpos {

void CheckScenarioAgainstNs3(const Scenario& scenario) {
  std::lock_guard<std::mutex> lock(Ns3ObjectsMutex());
  PlanUavChannels(scenario);
  // Footprint buildings need a loss model that asks the venue's obstacles, not ns-3's boxes.
  GiveObstacles(
      scenario,
      CreateFromSpec(scenario.propagation, "/propagation", ns3::PropagationLossModel::GetTypeId()),
      nullptr, "/propagation");
  CreateFromSpec(scenario.wifi.rate_manager, "/wifi/rate_manager",
                 ns3::WifiRemoteStationManager::GetTypeId());
}

nlohmann::json ScenarioDocument(const std::string& file,
                                const std::vector<std::string>& overrides) {
  nlohmann::json document = ReadJsonFile(file);
  ApplyOverrides(document, overrides);
  return document;
}

Scenario LoadScenario(const std::string& file, const std::vector<std::string>& overrides) {
  const nlohmann::json document = ScenarioDocument(file, overrides);
  try {
    Scenario scenario = ParseScenario(document);
    CheckScenarioAgainstNs3(scenario);
    return scenario;
  } catch (const ConfigError& e) {
    throw BlameOverride(e, overrides);
  }
}

Vec3 ParsePosition(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  Vec3 p;
  char c1 = 0, c2 = 0;
  in >> p.x >> c1 >> p.y >> c2 >> p.z;
  if (in.fail() || c1 != ',' || c2 != ',' || !(in >> std::ws).eof()) {
    throw ConfigError(what, "expected x,y,z in metres, got \"" + text + "\"");
  }
  return p;
}

void CheckUavPosition(const Scenario& s, const Vec3& p, const std::string& what) {
  std::ostringstream where;
  where << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  if (p.x < 0 || p.x > s.venue.width || p.y < 0 || p.y > s.venue.depth || p.z < 0 ||
      p.z > s.venue.height) {
    throw ConfigError(what, where.str() + " is outside the venue");
  }
  const int inside = BuildingContaining(s, p);
  if (inside >= 0) {
    throw ConfigError(what, where.str() + " is inside building " + std::to_string(inside) + " (\"" +
                                s.buildings[inside].name + "\")");
  }
}

Placement ParsePlacement(const Scenario& s, const std::vector<std::string>& texts,
                         const std::string& what) {
  if (texts.size() != s.uavs.size()) {
    throw ConfigError(what, "scenario " + s.name + " has " + std::to_string(s.uavs.size()) +
                                " UAV(s): give one x,y,z each (" + std::to_string(texts.size()) +
                                " given)");
  }
  Placement placement;
  for (std::size_t u = 0; u < texts.size(); ++u) {
    const std::string where = texts.size() == 1 ? what : what + " #" + std::to_string(u + 1);
    placement.push_back(ParsePosition(texts[u], where));
    CheckUavPosition(s, placement.back(), where);
    for (std::size_t v = 0; v < u; ++v) {
      if (UavsOverlap(placement[u], placement[v])) {
        throw ConfigError(where, "UAVs " + s.uavs[v].name + " and " + s.uavs[u].name +
                                     " overlap: they must be at least 1 m apart");
      }
    }
  }
  return placement;
}

}  // namespace rlpos
