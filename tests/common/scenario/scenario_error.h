#pragma once
// For the scenario parser's tests: a shipped scenario's document, and what a document fails with.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {

// The document of a scenario shipped in campaigns/scenarios ("b": b.json).
inline nlohmann::json ShippedScenarioDocument(const std::string& name) {
  return ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json");
}

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
