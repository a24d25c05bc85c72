#include "worker/programs/sim_api/sim_options.h"

#include <utility>

#include "common/logging/log.h"
#include "worker/env/network/scenario_loading.h"

namespace rlpos::sim {

Scenario LoadScenarioFor(const CommonOptions& options, std::vector<std::string> extra) {
  std::vector<std::string> overrides = std::move(extra);
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  Scenario scenario = LoadScenario(options.scenario_file, overrides);
  SetLogLevel(ParseLogLevel(options.log_level.empty() ? scenario.log_level : options.log_level));
  return scenario;
}

}  // namespace rlpos::sim
