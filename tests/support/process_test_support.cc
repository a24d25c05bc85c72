#include "tests/support/process_test_support.h"

#include <filesystem>
#include <sstream>

namespace rlpos::testing {

std::vector<pid_t> LiveProcessesOfGroup(pid_t pgid) {
  std::vector<pid_t> live;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos)
      continue;
    // /proc/<pid>/stat: "pid (comm) state ppid pgrp ..."; comm may hold spaces and ')'.
    const std::string stat = ReadFile(entry.path().string() + "/stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos)
      continue;  // ended meanwhile
    std::istringstream fields(stat.substr(close + 1));
    char state = 0;
    long ppid = 0, pgrp = 0;
    if (!(fields >> state >> ppid >> pgrp))
      continue;
    if (pgrp == pgid && state != 'Z' && state != 'X')
      live.push_back(std::stoi(name));
  }
  return live;
}

}  // namespace rlpos::testing
