#pragma once
// Shared helpers of the process tests: a temporary folder, files, waiting with a deadline, and
// which processes of a group are still alive.
#include <sys/types.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "support/wait_for.h"

namespace rlpos::testing {

// A fresh folder under the system's temp dir, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::string ReadFile(const std::string& file);
void WriteFile(const std::string& file, const std::string& text);

// Pids of the processes in group `pgid` that have not ended. Zombies count as ended: the
// orphans of a killed group are reaped by whoever adopted them, maybe not at once.
std::vector<pid_t> LiveProcessesOfGroup(pid_t pgid);

}  // namespace rlpos::testing
