#pragma once
// A child process (a worker's rlpos-sim job, or a daemon of the embedded runner): started in
// its own process group with stdout and stderr going to files, polled without blocking, killed
// with its whole group.
// An ns-3 abort, a crash or a hang of the child never touches its parent.
#include <sys/types.h>

#include <string>
#include <vector>

namespace rlpos {

struct ChildExit {
  bool exited = false;  // true: exit code; false: killed by `signal`
  int code = 0;
  int signal = 0;
};

// "exit code 2", "signal 6 (Aborted)".
std::string Describe(const ChildExit& exit);

class ChildProcess {
 public:
  // Throws std::runtime_error when fork or the output files fail; an exec failure shows as
  // exit code 127 with the reason in the stderr file.
  ChildProcess(const std::vector<std::string>& argv, const std::string& stdout_file,
               const std::string& stderr_file);
  ~ChildProcess();  // kills the group if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Non-blocking; true once the child has ended (then exit_status() is valid).
  bool Poll();
  const ChildExit& exit_status() const { return exit_; }
  // SIGTERM to the group without waiting (stop several children at once, then Kill each).
  void Terminate();
  // SIGTERM to the group, then SIGKILL if it has not ended after `grace_s`; waits for it.
  void Kill(double grace_s = 1.0);
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  bool done_ = false;
  ChildExit exit_;
};

}  // namespace rlpos
