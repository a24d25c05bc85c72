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

// The JSON pointer of a dotted key, as --set takes it: "wifi.tx_power" -> "/wifi/tx_power".
inline std::string Pointer(const std::string& dotted_key) {
  std::string path = "/" + dotted_key;
  for (auto& c : path)
    c = (c == '.') ? '/' : c;
  return path;
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
