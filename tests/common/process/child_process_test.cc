#include "common/process/child_process.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <memory>
#include <stdexcept>

#include "tests/support/process_test_support.h"

namespace rlpos {
namespace {

using testing::LiveProcessesOfGroup;
using testing::ReadFile;
using testing::WaitFor;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool ProcessExists(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

class ChildProcessTest : public ::testing::Test {
 protected:
  std::unique_ptr<ChildProcess> Start(const std::vector<std::string>& argv) {
    return std::make_unique<ChildProcess>(argv, out_, err_);
  }
  std::unique_ptr<ChildProcess> Shell(const std::string& script) {
    return Start({"/bin/sh", "-c", script});
  }
  // Polls until the child ended; fails the test after 5 s.
  static void AwaitEnd(ChildProcess& child) {
    ASSERT_TRUE(WaitFor([&] { return child.Poll(); }, 5.0)) << "child " << child.pid();
  }

  testing::TempDir dir_;
  std::string out_ = dir_.File("stdout.txt"), err_ = dir_.File("stderr.txt");
};

TEST(Describe, ExitCodeAndSignal) {
  EXPECT_EQ(Describe(ChildExit{true, 2, 0}), "exit code 2");
  EXPECT_EQ(Describe(ChildExit{true, 0, 0}), "exit code 0");
  EXPECT_EQ(Describe(ChildExit{false, 0, SIGABRT}), "signal 6 (Aborted)");
  EXPECT_EQ(Describe(ChildExit{false, 0, SIGKILL}), "signal 9 (Killed)");
}

TEST(ShellStatus, ExitCodeOr128PlusTheSignal) {
  EXPECT_EQ(ShellStatus(ChildExit{true, 2, 0}), 2);
  EXPECT_EQ(ShellStatus(ChildExit{true, 0, 0}), 0);
  EXPECT_EQ(ShellStatus(ChildExit{false, 0, SIGABRT}), 134);
  EXPECT_EQ(ShellStatus(ChildExit{false, 0, SIGKILL}), 137);
}

TEST(RunProcess, CollectsStdoutAndStderrInterleavedWithTheExitCode) {
  const ProcessResult run =
      RunProcess({"/bin/sh", "-c", "echo out; echo err >&2; echo out2; exit 3"});
  EXPECT_TRUE(run.started);
  EXPECT_TRUE(run.exit.exited);
  EXPECT_EQ(run.exit.code, 3);
  EXPECT_EQ(run.output, "out\nerr\nout2\n");
}

TEST(RunProcess, LooksTheProgramUpInPathWithStdinEmpty) {
  const ProcessResult run = RunProcess({"sh", "-c", "cat; echo done"});
  EXPECT_TRUE(run.started);
  EXPECT_EQ(ShellStatus(run.exit), 0);
  EXPECT_EQ(run.output, "done\n");
}

TEST(RunProcess, DeathBySignalIs128PlusTheSignal) {
  const ProcessResult run = RunProcess({"/bin/sh", "-c", "kill -KILL $$"});
  EXPECT_TRUE(run.started);
  EXPECT_FALSE(run.exit.exited);
  EXPECT_EQ(run.exit.signal, SIGKILL);
  EXPECT_EQ(ShellStatus(run.exit), 137);
}

TEST(RunProcess, AProgramThatCannotRunIsNotStartedWithTheReason) {
  ProcessResult run = RunProcess({"rlpos-no-such-program", "--flag"});
  EXPECT_FALSE(run.started);
  EXPECT_EQ(run.output, "rlpos-no-such-program: No such file or directory");
  run = RunProcess({"/nonexistent/python3", "script.py"});
  EXPECT_FALSE(run.started);
  EXPECT_EQ(run.output, "/nonexistent/python3: No such file or directory");
  testing::TempDir dir;
  const std::string plain = dir.File("not-executable");
  testing::WriteFile(plain, "#!/bin/sh\necho ran\n");
  run = RunProcess({plain});
  EXPECT_FALSE(run.started);
  EXPECT_EQ(run.output, plain + ": Permission denied");
  run = RunProcess({});
  EXPECT_FALSE(run.started);
  EXPECT_EQ(run.output, "no program given");
}

// The shell's "not found / not run", whoever says it.
TEST(RunProcess, ExitCode127IsNotStarted) {
  const ProcessResult run = RunProcess({"/bin/sh", "-c", "echo missing >&2; exit 127"});
  EXPECT_FALSE(run.started);
  EXPECT_EQ(run.output, "missing\n");
}

TEST_F(ChildProcessTest, ExitCodeAndOutputFiles) {
  auto child = Shell("echo to-out; echo to-err >&2; exit 3");
  EXPECT_GT(child->pid(), 0);
  AwaitEnd(*child);
  EXPECT_TRUE(child->exit_status().exited);
  EXPECT_EQ(child->exit_status().code, 3);
  EXPECT_EQ(Describe(child->exit_status()), "exit code 3");
  EXPECT_EQ(ReadFile(out_), "to-out\n");
  EXPECT_EQ(ReadFile(err_), "to-err\n");
  EXPECT_TRUE(child->Poll());  // stays ended
  EXPECT_EQ(child->exit_status().code, 3);
}

TEST_F(ChildProcessTest, OutputFilesAreTruncated) {
  testing::WriteFile(out_, "old text that is longer than the new one\n");
  auto child = Shell("echo new");
  AwaitEnd(*child);
  EXPECT_EQ(ReadFile(out_), "new\n");
  EXPECT_EQ(ReadFile(err_), "");
}

TEST_F(ChildProcessTest, StdinIsEmpty) {
  auto child = Shell("cat; echo done");  // would block on an inherited terminal or pipe
  AwaitEnd(*child);
  EXPECT_EQ(child->exit_status().code, 0);
  EXPECT_EQ(ReadFile(out_), "done\n");
}

TEST_F(ChildProcessTest, DeathBySignalIsDescribed) {
  auto child = Shell("kill -KILL $$");
  AwaitEnd(*child);
  EXPECT_FALSE(child->exit_status().exited);
  EXPECT_EQ(child->exit_status().signal, SIGKILL);
  EXPECT_EQ(Describe(child->exit_status()), "signal 9 (Killed)");
}

TEST_F(ChildProcessTest, ExecFailureIsExitCode127WithTheReason) {
  auto child = Start({"/nonexistent/rlpos-sim", "eval"});
  AwaitEnd(*child);
  EXPECT_TRUE(child->exit_status().exited);
  EXPECT_EQ(child->exit_status().code, 127);
  EXPECT_EQ(ReadFile(err_), "cannot run /nonexistent/rlpos-sim: No such file or directory\n");
}

TEST_F(ChildProcessTest, BadArgumentsThrow) {
  EXPECT_THROW(ChildProcess({}, out_, err_), std::runtime_error);
  const std::string bad = dir_.File("missing/stdout.txt");
  try {
    ChildProcess child({"/bin/true"}, bad, err_);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
  const std::string bad_err = dir_.File("missing/stderr.txt");
  try {
    ChildProcess child({"/bin/true"}, out_, bad_err);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad_err), std::string::npos) << e.what();
  }
}

TEST_F(ChildProcessTest, PollDoesNotBlock) {
  auto child = Start({"/bin/sleep", "100"});
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(child->Poll());
  EXPECT_FALSE(child->Poll());
  EXPECT_LT(SecondsSince(start), 0.5);
  child->Kill(0.5);
}

TEST_F(ChildProcessTest, KillStopsASleepingChild) {
  auto child = Start({"/bin/sleep", "100"});
  const pid_t pid = child->pid();
  ASSERT_TRUE(ProcessExists(pid));
  const auto start = std::chrono::steady_clock::now();
  child->Kill(2.0);
  EXPECT_LT(SecondsSince(start), 1.5);  // sleep ends on SIGTERM: no need for the grace period
  EXPECT_TRUE(child->Poll());
  EXPECT_FALSE(child->exit_status().exited);
  EXPECT_EQ(child->exit_status().signal, SIGTERM);
  EXPECT_FALSE(ProcessExists(pid));  // ended and reaped
}

TEST_F(ChildProcessTest, KillReachesTheWholeGroup) {
  auto child = Shell("sleep 100 & sleep 100; echo not-killed");
  const pid_t group = child->pid();
  // The shell and both sleeps, all in the child's own group (not ours).
  ASSERT_TRUE(WaitFor([&] { return LiveProcessesOfGroup(group).size() >= 3; }, 5.0))
      << LiveProcessesOfGroup(group).size();
  EXPECT_NE(::getpgrp(), group);
  child->Kill(1.0);
  EXPECT_TRUE(WaitFor([&] { return LiveProcessesOfGroup(group).empty(); }, 5.0))
      << LiveProcessesOfGroup(group).size() << " still alive";
  EXPECT_EQ(ReadFile(out_), "");
}

TEST_F(ChildProcessTest, KillEscalatesToSigkillAfterTheGrace) {
  // SIGTERM ignored by the shell and, inherited, by its sleep.
  auto child = Shell("trap '' TERM; sleep 100; echo survived");
  const pid_t group = child->pid();
  ASSERT_TRUE(WaitFor([&] { return LiveProcessesOfGroup(group).size() >= 2; }, 5.0));
  const auto start = std::chrono::steady_clock::now();
  child->Kill(0.3);
  const double took = SecondsSince(start);
  EXPECT_GE(took, 0.29);
  EXPECT_LT(took, 3.0);
  EXPECT_EQ(child->exit_status().signal, SIGKILL);
  EXPECT_TRUE(WaitFor([&] { return LiveProcessesOfGroup(group).empty(); }, 5.0));
  EXPECT_EQ(ReadFile(out_), "");
}

TEST_F(ChildProcessTest, TerminateSendsSigtermWithoutWaiting) {
  auto child = Start({"/bin/sleep", "100"});
  child->Terminate();
  AwaitEnd(*child);
  EXPECT_EQ(child->exit_status().signal, SIGTERM);
}

TEST_F(ChildProcessTest, DestructorKillsARunningChild) {
  pid_t pid = 0;
  {
    auto child = Start({"/bin/sleep", "100"});
    pid = child->pid();
    ASSERT_TRUE(ProcessExists(pid));
  }
  EXPECT_FALSE(ProcessExists(pid));
}

}  // namespace
}  // namespace rlpos
