#pragma once
// For rlpos-sim's tests: the program as a user runs it, and the scenarios shipped with it.
#include <string>

#include "tests/support/command.h"

namespace rlpos::testing {

// The folder of the shipped scenarios ("<source>/campaigns/scenarios/"), and scenario B's file.
inline const std::string kScenarios = std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/";
inline const std::string kScenarioB = kScenarios + "b.json";

// The command line "<build>/bin/rlpos-sim ARGS".
inline std::string Sim(const std::string& args) {
  return BuiltBinary("rlpos-sim") + " " + args;
}

}  // namespace rlpos::testing
