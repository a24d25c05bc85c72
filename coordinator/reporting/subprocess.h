#pragma once
// Runs a helper program (the plotting script) and collects what it prints, without a shell, so
// that paths with spaces or quotes need no escaping and a missing interpreter is an ordinary
// outcome rather than an exception.
#include <string>
#include <vector>

namespace rlpos {

struct ProcessResult {
  bool started = false;  // false: the program could not be run (not found, not executable)
  int exit_code = -1;    // its exit status; 128 + N when killed by signal N
  std::string output;    // stdout and stderr interleaved; `error` when it did not start
};

// argv[0] is looked up in PATH when it has no '/'. stdin is /dev/null. Waits for the end.
ProcessResult RunProcess(const std::vector<std::string>& argv);

}  // namespace rlpos
