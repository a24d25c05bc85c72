#include "common/process/child_process.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace rlpos {
namespace {

ChildExit FromWaitStatus(int status) {
  ChildExit e;
  if (WIFEXITED(status)) {
    e.exited = true;
    e.code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    e.signal = WTERMSIG(status);
  }
  return e;
}

int OpenOutput(const std::string& file) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(file + ": " + std::strerror(errno));
  return fd;
}

}  // namespace

std::string Describe(const ChildExit& exit) {
  if (exit.exited)
    return "exit code " + std::to_string(exit.code);
  return "signal " + std::to_string(exit.signal) + " (" + strsignal(exit.signal) + ")";
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::string& stdout_file,
                           const std::string& stderr_file) {
  if (argv.empty())
    throw std::runtime_error("empty command line");
  const int out = OpenOutput(stdout_file);
  int err = -1;
  try {
    err = OpenOutput(stderr_file);
  } catch (...) {
    ::close(out);
    throw;
  }
  // Everything the child needs is prepared before vfork: the child shares this memory until it
  // execs, so it only makes system calls, touching no heap and no lock. (fork copied the
  // page tables of a large, threaded process, and every page the parent then wrote took a
  // copy-on-write fault: most of a worker's CPU per job.)
  std::vector<char*> args;
  for (const auto& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = ::getpid();
  // No signal handler of ours may run in the child while it shares our memory: all signals are
  // blocked around vfork; the child resets the handlers to their defaults, then restores the
  // mask for the program it runs.
  sigset_t all, previous;
  ::sigfillset(&all);
  ::pthread_sigmask(SIG_SETMASK, &all, &previous);
  pid_ = ::vfork();
  if (pid_ == 0) {
    for (int s = 1; s < NSIG; ++s) {
      struct sigaction action;
      if (::sigaction(s, nullptr, &action) == 0 && action.sa_handler != SIG_IGN &&
          action.sa_handler != SIG_DFL) {
        action.sa_handler = SIG_DFL;
        action.sa_flags = 0;
        ::sigaction(s, &action, nullptr);
      }
    }
    ::setpgid(0, 0);  // its own group: a kill reaches whatever it starts, never the parent
    // Dies with its parent: a killed worker leaves no job running unseen.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent)
      ::_exit(127);  // the parent died before prctl
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0)
      ::dup2(devnull, STDIN_FILENO);
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    ::execv(args[0], args.data());
    // strerrordesc_np: a constant string, no locale, no allocation.
    const char* reason = ::strerrordesc_np(errno);
    if (reason == nullptr)
      reason = "unknown error";
    const char prefix[] = "cannot run ";
    (void)!::write(STDERR_FILENO, prefix, sizeof prefix - 1);
    (void)!::write(STDERR_FILENO, args[0], std::strlen(args[0]));
    (void)!::write(STDERR_FILENO, ": ", 2);
    (void)!::write(STDERR_FILENO, reason, std::strlen(reason));
    (void)!::write(STDERR_FILENO, "\n", 1);
    ::_exit(127);
  }
  const int vfork_error = errno;
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (pid_ < 0) {
    ::close(out);
    ::close(err);
    throw std::runtime_error(std::string("vfork: ") + std::strerror(vfork_error));
  }
  ::setpgid(pid_, pid_);  // also from the parent: no race with an early Kill
  ::close(out);
  ::close(err);
}

ChildProcess::~ChildProcess() {
  if (!done_)
    Kill(0.2);
}

bool ChildProcess::Poll() {
  if (done_)
    return true;
  int status = 0;
  const pid_t r = ::waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    exit_ = FromWaitStatus(status);
    done_ = true;
  }
  return done_;
}

void ChildProcess::Terminate() {
  if (!done_)
    ::kill(-pid_, SIGTERM);
}

void ChildProcess::Kill(double grace_s) {
  if (done_)
    return;
  ::kill(-pid_, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (Poll())
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid_, SIGKILL);  // the rest of the group too, even if the leader ended
  if (!done_) {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exit_ = FromWaitStatus(status);
    done_ = true;
  }
}

}  // namespace rlpos
