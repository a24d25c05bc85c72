#pragma once
// For rlpos-sim's tests: the program as a user runs it, and the scenarios shipped with it.
#include <gtest/gtest.h>

#include <algorithm>
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

// A refused --policy: exit 2, nothing on stdout, one line on stderr in the program's format
// that names the policy (its folder or file) and the field.
inline void ExpectOneLineRefusal(const CommandResult& r, const std::string& policy,
                                 const std::string& field) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rlpos-sim: error: --policy: " + policy, 0), 0u) << r.err;
  EXPECT_NE(r.err.find(field), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace rlpos::testing
