#pragma once
// The usage of the small programs built beside the tests (benchmarks, the hostile peer): asked
// for (--help or -h anywhere), on stdout with exit 0, as every program in bin/ answers --help
// (tests/worker/programs/rlpos_sim/help_test.cc runs them all); a wrong argument count, on stderr
// with exit 2.
#include <cstdio>
#include <cstring>

namespace rlpos::testing {

// Whether an argument asks for help; if one does, `usage` (its lines, each ending in a newline)
// is printed on stdout.
inline bool PrintedHelp(int argc, char** argv, const char* usage) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::fputs(usage, stdout);
      return true;
    }
  }
  return false;
}

// `usage` on stderr, for a wrong argument count: the exit code to return (2).
inline int UsageError(const char* usage) {
  std::fputs(usage, stderr);
  return 2;
}

}  // namespace rlpos::testing
