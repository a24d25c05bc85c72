#pragma once
// For the scenario parser's tests: what a document fails with.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {

// Parses `doc` after applying `overrides`; returns the error ("<path>: <problem>") or "".
inline std::string ErrorOf(nlohmann::json doc, const std::vector<std::string>& overrides) {
  try {
    ApplyOverrides(doc, overrides);
    ParseScenario(doc);
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

}  // namespace rlpos
