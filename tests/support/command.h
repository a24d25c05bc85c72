#pragma once
// Runs a command line through the shell and captures its exit code, stdout and stderr.
#include <string>

namespace rlpos::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

CommandResult RunCommand(const std::string& command_line);

// Path of a binary built by this project (next to the test binary).
std::string BuiltBinary(const std::string& name);

}  // namespace rlpos::testing
