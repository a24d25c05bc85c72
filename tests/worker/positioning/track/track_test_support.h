#pragma once
// For the track tests: a shipped scenario, and a generated one whose UEs walk.
#include <string>
#include <vector>

#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/network/scenario_loading.h"

namespace rlpos::testing {

inline Scenario Shipped(const std::string& name, std::vector<std::string> overrides = {}) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json",
                      overrides);
}

// A campus of `uavs` UAVs whose UEs walk random waypoints (RngRun `run`), on a 10 m grid with a
// decision every second: a few oracle decisions stay quick.
inline Scenario Walking(int uavs, std::uint64_t run = 1) {
  GeneratorOptions options;
  options.seed = 4;
  options.style = GeneratorStyle::kCampus;
  options.uavs = uavs;
  options.mobility = MobilityModel::kRandomWaypoint;
  Scenario s = GenerateScenario(options).scenario;
  s.env.step = 10.0;
  s.env.decision_interval = 1.0;
  s.simulation.run = run;
  return s;
}

}  // namespace rlpos::testing
