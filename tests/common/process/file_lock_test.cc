#include "common/process/file_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <memory>
#include <stdexcept>

#include "tests/support/process_test_support.h"

namespace rlpos {
namespace {

using testing::ReadFile;

// The message of the std::runtime_error that locking `file` throws ("" and a failure if none).
std::string LockError(const std::string& file) {
  try {
    ExclusiveFileLock lock(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "the lock on " << file << " was granted";
  return "";
}

// Runs `body` in a forked child and returns its exit code (the test process has no threads).
template <typename F>
int InChild(F body) {
  const pid_t pid = ::fork();
  if (pid == 0)
    ::_exit(body());
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(ExclusiveFileLock, HolderWritesItsPid) {
  testing::TempDir dir;
  const std::string file = dir.File("coordinator.lock");
  ExclusiveFileLock lock(file);
  EXPECT_EQ(ReadFile(file), std::to_string(::getpid()));
}

TEST(ExclusiveFileLock, SecondLockInTheSameProcessFailsNamingTheFile) {
  testing::TempDir dir;
  const std::string file = dir.File("coordinator.lock");
  auto first = std::make_unique<ExclusiveFileLock>(file);
  // flock locks belong to the open file description: a second open conflicts even here.
  const std::string error = LockError(file);
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_NE(error.find("held by another process"), std::string::npos) << error;
  EXPECT_NE(error.find("(pid " + std::to_string(::getpid()) + ")"), std::string::npos) << error;
  EXPECT_EQ(ReadFile(file), std::to_string(::getpid()));  // the failed attempt changed nothing

  first.reset();
  EXPECT_NO_THROW(ExclusiveFileLock again(file));
  EXPECT_NO_THROW(ExclusiveFileLock once_more(file));
}

TEST(ExclusiveFileLock, OtherProcessIsRefusedWhileHeld) {
  testing::TempDir dir;
  const std::string file = dir.File("coordinator.lock");
  const auto try_lock = [&] {
    try {
      ExclusiveFileLock lock(file);
      return 0;
    } catch (const std::runtime_error&) {
      return 1;
    }
  };
  {
    ExclusiveFileLock lock(file);
    EXPECT_EQ(InChild(try_lock), 1);
  }
  EXPECT_EQ(InChild(try_lock), 0);
}

TEST(ExclusiveFileLock, KilledHolderReleasesTheLock) {
  testing::TempDir dir;
  const std::string file = dir.File("coordinator.lock");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t holder = ::fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {
    ::close(ready[0]);
    try {
      ExclusiveFileLock lock(file);
      (void)!::write(ready[1], "1", 1);
      for (;;)
        ::pause();
    } catch (...) {
      ::_exit(1);
    }
  }
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1) << "the holder did not get the lock";
  ::close(ready[0]);
  const std::string error = LockError(file);
  EXPECT_NE(error.find("(pid " + std::to_string(holder) + ")"), std::string::npos) << error;

  ::kill(holder, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(holder, &status, 0), holder);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_NO_THROW(ExclusiveFileLock lock(file));
}

TEST(ExclusiveFileLock, UncreatableFileThrowsNamingIt) {
  testing::TempDir dir;
  const std::string file = dir.File("no-such-folder/coordinator.lock");
  const std::string error = LockError(file);
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

}  // namespace
}  // namespace rlpos
