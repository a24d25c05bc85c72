// The benches' arguments: a bad scenario file, position or duration is a one-line error and a
// non-zero exit before any simulation runs.
#include <gtest/gtest.h>

#include "tests/support/command.h"

namespace rlpos::testing {
namespace {

const std::string kScenarioA = std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/a.json";

void ExpectOneLineError(const std::string& command_line, const std::string& message) {
  const CommandResult r = RunCommand(command_line);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err, "error: " + message + "\n");
}

TEST(BenchCli, AccessRejectsBadArguments) {
  const std::string bench = BuiltBinary("rlpos-bench-access");
  ExpectOneLineError(bench + " /nonexistent.json 1,2,3", "/nonexistent.json: /: cannot open file");
  ExpectOneLineError(bench + " " + kScenarioA + " 1,2",
                     "position: expected x,y,z in metres, got \"1,2\"");
  ExpectOneLineError(bench + " " + kScenarioA + " 1,2,3 -1",
                     "duration: -1 is not a positive number of seconds");
}

TEST(BenchCli, CalibrationRejectsBadArguments) {
  const std::string bench = BuiltBinary("rlpos-bench-calibration");
  ExpectOneLineError(bench + " /nonexistent.json", "/nonexistent.json: /: cannot open file");
  ExpectOneLineError(bench + " " + kScenarioA + " 2s",
                     "duration: 2s is not a positive number of seconds");
}

}  // namespace
}  // namespace rlpos::testing
