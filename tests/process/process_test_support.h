#pragma once
// Shared helpers of the process tests: a temporary folder, files, waiting with a deadline, and
// which processes of a group are still alive.
#include <sys/types.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

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

// Calls `done` every 20 ms until it returns true or `timeout_s` passed; returns its last answer.
template <typename F>
bool WaitFor(F done, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    if (done())
      return true;
    if (std::chrono::steady_clock::now() >= deadline)
      return done();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace rlpos::testing
