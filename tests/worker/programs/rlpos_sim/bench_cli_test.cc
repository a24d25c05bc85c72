// The benches' arguments: a bad scenario file, position, duration or step count is a one-line
// error and a non-zero exit before any simulation runs.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

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

// `bench` run with each row's arguments: the row's one-line error.
void ExpectOneLineErrors(const std::string& bench,
                         const std::vector<std::pair<std::string, std::string>>& rows) {
  for (const auto& [arguments, message] : rows)
    ExpectOneLineError(bench + " " + arguments, message);
}

const std::string kMissingScenario = "/nonexistent.json: cannot open: No such file or directory";

TEST(BenchCli, AccessRejectsBadArguments) {
  ExpectOneLineErrors(
      BuiltBinary("rlpos-bench-access"),
      {{"/nonexistent.json 1,2,3", kMissingScenario},
       {kScenarioA + " 1,2", "position: expected x,y,z in metres, got \"1,2\""},
       {kScenarioA + " 1,2,3 -1", "duration: -1 is not a positive number of seconds"}});
}

TEST(BenchCli, CalibrationRejectsBadArguments) {
  ExpectOneLineErrors(BuiltBinary("rlpos-bench-calibration"),
                      {{"/nonexistent.json", kMissingScenario},
                       {kScenarioA + " 2s", "duration: 2s is not a positive number of seconds"}});
}

// rlpos-bench-env once aborted on --help (it took it for the scenario file): its usage now, and
// each bad argument a line.
TEST(BenchCli, EnvAnswersHelpAndRejectsBadArguments) {
  const std::string bench = BuiltBinary("rlpos-bench-env");
  const std::string usage =
      "usage: rlpos-bench-env SCENARIO.json [ANALYTIC_STEPS] [PACKET_STEPS] [ENV_ALONE_STEPS]\n";
  const CommandResult help = RunCommand(bench + " --help");
  EXPECT_EQ(help.exit_code, 0) << help.err;
  EXPECT_EQ(help.out, usage);
  const CommandResult none = RunCommand(bench);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err, usage);
  ExpectOneLineErrors(
      bench,
      {{"/nonexistent.json", kMissingScenario},
       {kScenarioA + " 10 0", "PACKET_STEPS: expected a positive whole number of steps, got \"0\""},
       {kScenarioA + " 2k",
        "ANALYTIC_STEPS: expected a positive whole number of steps, got \"2k\""}});
}

}  // namespace
}  // namespace rlpos::testing
