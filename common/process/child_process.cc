#include "common/process/child_process.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>
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

// Where execvp would look for `file`: itself when it has a '/', else in each folder of PATH
// (glibc's default when PATH is unset; an empty entry is the current folder).
std::vector<std::string> SearchPath(const std::string& file) {
  if (file.find('/') != std::string::npos)
    return {file};
  if (file.empty())
    return {};
  const char* path = std::getenv("PATH");
  const std::string folders = path != nullptr ? path : "/bin:/usr/bin";
  std::vector<std::string> out;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = folders.find(':', begin);
    const std::string folder = folders.substr(begin, end - begin);
    out.push_back(folder.empty() ? file : folder + "/" + file);
    if (end == std::string::npos)
      break;
    begin = end + 1;
  }
  return out;
}

// In the vfork child: execs the first of `paths` that runs, trying the next as execvp does
// (after "not found" or "not allowed"); the errno when none does (EACCES when one was not
// allowed, ENOENT when there was none). System calls only.
int ExecFirst(const char* const* paths, std::size_t count, char* const* args) {
  int error = ENOENT;
  bool denied = false;
  for (std::size_t i = 0; i < count; ++i) {
    ::execv(paths[i], args);
    error = errno;
    switch (error) {
      case EACCES:
        denied = true;
        break;
      case ENOENT:
      case ESTALE:
      case ENOTDIR:
      case ENODEV:
      case ETIMEDOUT:
        break;
      default:
        return error;
    }
  }
  return denied ? EACCES : error;
}

}  // namespace

std::string Describe(const ChildExit& exit) {
  if (exit.exited)
    return "exit code " + std::to_string(exit.code);
  return "signal " + std::to_string(exit.signal) + " (" + strsignal(exit.signal) + ")";
}

int ShellStatus(const ChildExit& exit) {
  return exit.exited ? exit.code : 128 + exit.signal;
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
  try {
    Start(argv, {argv[0]}, out, err);
  } catch (...) {
    ::close(out);
    ::close(err);
    throw;
  }
  ::close(out);
  ::close(err);
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, int output_fd) {
  if (argv.empty())
    throw std::runtime_error("empty command line");
  Start(argv, SearchPath(argv[0]), output_fd, output_fd);
}

void ChildProcess::Start(const std::vector<std::string>& argv,
                         const std::vector<std::string>& programs, int out, int err) {
  // Everything the child needs is prepared before vfork: the child shares this memory until it
  // execs, so it only makes system calls, touching no heap and no lock. (fork copied the
  // page tables of a large, threaded process, and every page the parent then wrote took a
  // copy-on-write fault: most of a worker's CPU per job.)
  std::vector<char*> args;
  for (const auto& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<const char*> paths;
  for (const auto& p : programs)
    paths.push_back(p.c_str());
  const pid_t parent = ::getpid();
  // Written by the child, which shares this memory until it execs or exits: the parent reads it
  // once vfork returns.
  volatile int exec_error = 0;
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
    const int error = ExecFirst(paths.data(), paths.size(), args.data());
    exec_error = error;
    // strerrordesc_np: a constant string, no locale, no allocation.
    const char* reason = ::strerrordesc_np(error);
    if (reason == nullptr)
      reason = "unknown error";
    const char* program = paths.empty() ? args[0] : paths.front();
    const char prefix[] = "cannot run ";
    (void)!::write(STDERR_FILENO, prefix, sizeof prefix - 1);
    (void)!::write(STDERR_FILENO, program, std::strlen(program));
    (void)!::write(STDERR_FILENO, ": ", 2);
    (void)!::write(STDERR_FILENO, reason, std::strlen(reason));
    (void)!::write(STDERR_FILENO, "\n", 1);
    ::_exit(127);
  }
  const int vfork_error = errno;
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (pid_ < 0)
    throw std::runtime_error(std::string("vfork: ") + std::strerror(vfork_error));
  exec_error_ = exec_error;
  ::setpgid(pid_, pid_);  // also from the parent: no race with an early Kill
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

const ChildExit& ChildProcess::Wait() {
  if (done_)
    return exit_;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0) {
    if (errno != EINTR)
      throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
  }
  exit_ = FromWaitStatus(status);
  done_ = true;
  return exit_;
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

ProcessResult RunProcess(const std::vector<std::string>& argv) {
  ProcessResult result;
  if (argv.empty()) {
    result.output = "no program given";
    return result;
  }
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    result.output = std::string("pipe failed: ") + std::strerror(errno);
    return result;
  }
  std::unique_ptr<ChildProcess> child;
  try {
    child = std::make_unique<ChildProcess>(argv, pipe_fds[1]);
  } catch (const std::exception& e) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    result.output = argv[0] + ": " + e.what();
    return result;
  }
  ::close(pipe_fds[1]);
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      break;
    result.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  try {
    result.exit = child->Wait();
  } catch (const std::exception& e) {
    result.output += e.what();
    return result;
  }
  if (child->exec_error() != 0) {
    result.output = argv[0] + ": " + std::strerror(child->exec_error());
    return result;
  }
  // The shell's convention for "not found / not run".
  result.started = !result.exit.exited || result.exit.code != 127;
  return result;
}

}  // namespace rlpos
