// Every program in the bin folder answers --help with its usage on stdout and exit 0, and so does
// each subcommand of those that list subcommands (rlpos-sim, rlpos-campaign and theirs): a user's
// first command must not abort, whatever program it is (rlpos-bench-env's once did).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/command.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

// The subcommands CLI11's help lists, under "SUBCOMMANDS:" up to the next blank line.
std::vector<std::string> SubcommandsIn(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream lines(help);
  bool listing = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("SUBCOMMANDS:", 0) == 0 || line.rfind("Subcommands:", 0) == 0) {
      listing = true;
    } else if (listing && line.find_first_not_of(' ') == std::string::npos) {
      listing = false;
    } else if (listing) {
      std::istringstream words(line);
      std::string name;
      words >> name;
      names.push_back(name);
    }
  }
  return names;
}

// Runs "COMMAND --help" (at most 60 s: a program that ignores --help must not start its work
// for good), expects exit 0 and a usage on stdout, then does the same for each subcommand it
// lists. `checked` collects what ran.
void ExpectHelp(const std::string& command, std::vector<std::string>& checked, int depth = 0) {
  const CommandResult r = RunCommand("timeout 60 " + command + " --help </dev/null");
  checked.push_back(command);
  EXPECT_EQ(r.exit_code, 0) << command << " --help\n" << r.err;
  EXPECT_FALSE(r.out.empty()) << command << " --help printed no usage on stdout\n" << r.err;
  if (depth >= 2)
    return;
  for (const std::string& sub : SubcommandsIn(r.out))
    ExpectHelp(command + " " + sub, checked, depth + 1);
}

TEST(ProgramHelp, EveryProgramAndSubcommandAnswersHelp) {
  std::set<std::string> programs;
  for (const auto& entry : fs::directory_iterator(RLPOS_BIN_DIR)) {
    const fs::perms exec = fs::perms::owner_exec;
    if (entry.is_regular_file() && (entry.status().permissions() & exec) != fs::perms::none)
      programs.insert(entry.path().filename().string());
  }
  // The programs a user meets first must be among them (this test's build depends on them).
  for (const char* expected :
       {"rlpos-sim", "rlpos-campaign", "rlpos-coordinator", "rlpos-worker", "rlpos-bench-env"}) {
    EXPECT_TRUE(programs.count(expected)) << expected << " is not in " << RLPOS_BIN_DIR;
  }
  std::vector<std::string> checked;
  for (const std::string& program : programs)
    ExpectHelp(BuiltBinary(program), checked);
  // rlpos-sim's and rlpos-campaign's subcommands were found and asked as well.
  const auto asked = [&](const std::string& command) {
    return std::find(checked.begin(), checked.end(), BuiltBinary(command)) != checked.end();
  };
  EXPECT_TRUE(asked("rlpos-sim train"));
  EXPECT_TRUE(asked("rlpos-campaign serve"));
  std::printf("%zu commands answered --help\n", checked.size());
}

// The four programs a package installs say their release and commit (docs/installing.md).
TEST(ProgramVersion, TheFourProgramsPrintTheirReleaseAndCommit) {
  for (const char* program : {"rlpos-sim", "rlpos-campaign", "rlpos-coordinator", "rlpos-worker"}) {
    const CommandResult r = RunCommand("timeout 60 " + BuiltBinary(program) + " --version");
    EXPECT_EQ(r.exit_code, 0) << program << " --version\n" << r.err;
    const std::string first = r.out.substr(0, r.out.find('\n'));
    EXPECT_EQ(first.rfind(std::string(program) + " " + RLPOS_RELEASE + " (commit ", 0), 0u)
        << program << " --version: " << first;
    EXPECT_NE(r.out.find("ns-3 "), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace rlpos::testing
