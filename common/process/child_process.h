#pragma once
// The one way RLpos starts a program: a child process (a worker's rlpos-sim job, a daemon of the
// embedded runner, a report's plotting script or map), started in its own process group with
// stdin from /dev/null, polled without blocking or waited for, killed with its whole group.
// An ns-3 abort, a crash or a hang of the child never touches its parent.
#include <sys/types.h>

#include <string>
#include <vector>

namespace rlpos {

// How a child ended: the one encoding of an exit status.
struct ChildExit {
  bool exited = false;  // true: exit code; false: killed by `signal`
  int code = 0;
  int signal = 0;
};

// "exit code 2", "signal 6 (Aborted)".
std::string Describe(const ChildExit& exit);
// The shell's number for it: the exit code, or 128 + the signal.
int ShellStatus(const ChildExit& exit);

class ChildProcess {
 public:
  // Runs argv (argv[0] a path) with stdout and stderr going to files. Throws std::runtime_error
  // when fork or the output files fail; an exec failure shows as exit code 127 with the reason
  // in the stderr file.
  ChildProcess(const std::vector<std::string>& argv, const std::string& stdout_file,
               const std::string& stderr_file);
  // Runs argv with stdout and stderr both on `output_fd` (which the caller keeps and closes),
  // argv[0] looked up in PATH when it has no '/', as a shell does. Throws std::runtime_error
  // when fork fails; an exec failure shows as exit code 127 and exec_error().
  ChildProcess(const std::vector<std::string>& argv, int output_fd);
  ~ChildProcess();  // kills the group if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Non-blocking; true once the child has ended (then exit_status() is valid).
  bool Poll();
  // Blocks until the child has ended. Throws std::runtime_error if it cannot be waited for.
  const ChildExit& Wait();
  const ChildExit& exit_status() const { return exit_; }
  // The errno of the exec that failed (the child then exits with code 127), or 0.
  int exec_error() const { return exec_error_; }
  // SIGTERM to the group without waiting (stop several children at once, then Kill each).
  void Terminate();
  // SIGTERM to the group, then SIGKILL if it has not ended after `grace_s`; waits for it.
  void Kill(double grace_s = 1.0);
  pid_t pid() const { return pid_; }

 private:
  // Execs the first of `programs` that runs, as execvp tries PATH's folders.
  void Start(const std::vector<std::string>& argv, const std::vector<std::string>& programs,
             int out_fd, int err_fd);

  pid_t pid_ = -1;
  bool done_ = false;
  ChildExit exit_;
  int exec_error_ = 0;
};

// What RunProcess saw.
struct ProcessResult {
  bool started = false;  // false: the program could not be run (not found, not executable)
  ChildExit exit;        // valid when started
  std::string output;    // stdout and stderr interleaved; the reason when not started
};

// Runs argv to its end and collects what it prints, without a shell, so that paths with spaces
// or quotes need no escaping and a missing program is an ordinary outcome rather than an
// exception. argv[0] is looked up in PATH when it has no '/'. An exit code of 127 (the shell's
// "not found / not run") counts as not started.
ProcessResult RunProcess(const std::vector<std::string>& argv);

}  // namespace rlpos
