// A worker in another process: killed, it shows as "no writers" once its lease (2 s in the
// loopback config) runs out; stopped cleanly, as "disposed". The second process is this binary
// again (--rlpos-child-writer), started by fork + exec with its own participant.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "idl/dds/topics.h"
#include "tests/idl/dds/dds_test_support.h"
#include "common/process/child_process.h"

namespace rlpos {
namespace {

using testing::AwaitSample;
using testing::WaitFor;

class LivelinessTest : public ::testing::Test {
 protected:
  LivelinessTest()
      : options_(testing::TestOptions()), participant_(options_), reader_(participant_) {}

  // Starts the child writer (on our tag unless `tag` is given) and returns its first status.
  std::optional<Received<msg::WorkerStatus>> StartChild(const std::string& worker_id,
                                                        double timeout_s = 10.0,
                                                        const std::string& tag = "") {
    child_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{testing::SelfExecutable(), testing::kChildWriterFlag,
                                 std::to_string(options_.domain),
                                 tag.empty() ? options_.loopback_tag : tag, worker_id},
        dir_ + "/child.out", dir_ + "/child.err");
    return AwaitSample(
        reader_, [&](const auto& r) { return r.valid && r.data.worker_id == worker_id; },
        timeout_s);
  }
  std::string ChildOutput() const {
    std::string text;
    for (const char* name : {"/child.out", "/child.err"}) {
      if (FILE* f = std::fopen((dir_ + name).c_str(), "r")) {
        char buffer[512];
        std::size_t n = 0;
        while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0)
          text.append(buffer, n);
        std::fclose(f);
      }
    }
    return text;
  }
  void SetUp() override {
    char pattern[] = "/tmp/rlpos-dds-XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    child_.reset();
    std::remove((dir_ + "/child.out").c_str());
    std::remove((dir_ + "/child.err").c_str());
    ::rmdir(dir_.c_str());
  }

  DdsOptions options_;
  Participant participant_;
  Reader<msg::WorkerStatus> reader_;
  std::string dir_;
  std::unique_ptr<ChildProcess> child_;
};

TEST_F(LivelinessTest, KilledWriterShowsAsNoWritersNotDisposed) {
  const auto alive = StartChild("w-killed");
  ASSERT_TRUE(alive.has_value()) << "no status from the child: " << ChildOutput();
  EXPECT_EQ(alive->state, InstanceState::kAlive);
  EXPECT_EQ(alive->data.host, "child");
  EXPECT_EQ(alive->data.pid, child_->pid());
  EXPECT_EQ(alive->data.slots, 3);
  EXPECT_EQ(alive->data.busy, 1);
  EXPECT_EQ(alive->data.jobs, std::vector<std::string>{"j#1"});

  const auto killed_at = std::chrono::steady_clock::now();
  ASSERT_EQ(::kill(child_->pid(), SIGKILL), 0);
  ASSERT_TRUE(WaitFor([&] { return child_->Poll(); }));
  EXPECT_EQ(child_->exit_status().signal, SIGKILL);

  // Noticed by the 2 s lease of the loopback configuration, not Cyclone's default 10 s: the
  // bound (4 leases) is well under the wait's limit and under the default lease.
  const auto gone = AwaitSample(
      reader_, [](const auto& r) { return r.data.worker_id == "w-killed" && !r.valid; }, 30.0);
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - killed_at).count();
  ASSERT_TRUE(gone.has_value()) << "the lost writer was not noticed in 30 s";
  EXPECT_EQ(gone->state, InstanceState::kNoWriters);
  EXPECT_LT(took, 8.0) << "the 2 s lease did not apply";
  EXPECT_TRUE(WaitFor([&] { return reader_.MatchedWriters() == 0; }));
}

TEST_F(LivelinessTest, CleanlyStoppedWriterShowsAsDisposed) {
  const auto alive = StartChild("w-stopped");
  ASSERT_TRUE(alive.has_value()) << "no status from the child: " << ChildOutput();
  EXPECT_EQ(alive->state, InstanceState::kAlive);

  child_->Terminate();  // the child disposes its status, then exits
  const auto stopped = AwaitSample(
      reader_, [](const auto& r) { return r.data.worker_id == "w-stopped" && !r.valid; }, 5.0);
  ASSERT_TRUE(stopped.has_value()) << ChildOutput();
  EXPECT_EQ(stopped->state, InstanceState::kDisposed);
  ASSERT_TRUE(WaitFor([&] { return child_->Poll(); }));
  EXPECT_TRUE(child_->exit_status().exited);
  EXPECT_EQ(child_->exit_status().code, 0) << ChildOutput();
}

TEST_F(LivelinessTest, AnotherTagOnTheSameDomainIsNotSeen) {
  const std::string other_tag = testing::TestOptions().loopback_tag;
  ASSERT_NE(other_tag, options_.loopback_tag);
  const auto seen = StartChild("w-other", 1.5, other_tag);
  EXPECT_FALSE(seen.has_value()) << "a participant with another tag was discovered";
  EXPECT_EQ(reader_.MatchedWriters(), 0);
  // The child did run and write (it is not just slow): it said so.
  EXPECT_TRUE(WaitFor([&] { return ChildOutput().find("ready") != std::string::npos; }))
      << ChildOutput();
  EXPECT_FALSE(child_->Poll()) << ChildOutput();
}

}  // namespace
}  // namespace rlpos
