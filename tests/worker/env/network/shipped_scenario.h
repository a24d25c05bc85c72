#pragma once
// For the environment's tests: a scenario shipped in campaigns/scenarios, loaded as rlpos-sim
// loads it (with --set overrides).
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/network/scenario_loading.h"

namespace rlpos {

inline Scenario LoadShipped(const std::string& name, std::vector<std::string> overrides = {}) {
  return LoadScenario(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json",
                      overrides);
}

}  // namespace rlpos
