#pragma once
// The RLpos-3 config of these tests (data/rlpos3_full.json), and what importing it fails with.
#include <nlohmann/json.hpp>
#include <string>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_import/rlpos3_import.h"

namespace rlpos {

inline nlohmann::json FullRlpos3Config() {
  return ReadJsonFile(std::string(RLPOS_SOURCE_DIR) +
                      "/tests/common/scenario_import/data/rlpos3_full.json");
}

// The import's error ("<path>: <problem>") or "".
inline std::string ImportErrorOf(const nlohmann::json& config) {
  try {
    ImportRlpos3(config, "test");
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "";
}

}  // namespace rlpos
