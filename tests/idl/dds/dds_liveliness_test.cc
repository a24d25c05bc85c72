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

#include "common/process/child_process.h"
#include "idl/dds/topics.h"
#include "tests/idl/dds/dds_test_support.h"

namespace rlpos {
namespace {

using testing::AwaitSample;
using testing::WaitFor;

class LivelinessTest : public ::testing::Test {
 protected:
  LivelinessTest()
      : options_(testing::TestOptions()), participant_(options_), reader_(participant_) {}

  // Starts the child writer on our tag and returns its first status.
  std::optional<Received<msg::WorkerStatus>> StartChild(const std::string& worker_id) {
    child_ = StartChildMode(testing::kChildWriterFlag, options_.loopback_tag, worker_id, "child");
    return AwaitSample(
        reader_, [&](const auto& r) { return r.valid && r.data.worker_id == worker_id; }, 10.0);
  }
  // This binary in a child mode on our domain, its output in NAME.out and NAME.err.
  std::unique_ptr<ChildProcess> StartChildMode(const char* flag, const std::string& tag,
                                               const std::string& worker_id,
                                               const std::string& name) {
    return std::make_unique<ChildProcess>(
        std::vector<std::string>{testing::SelfExecutable(), flag, std::to_string(options_.domain),
                                 tag, worker_id},
        dir_ + "/" + name + ".out", dir_ + "/" + name + ".err");
  }
  std::string ChildOutput(const std::string& name = "child") const {
    std::string text;
    for (const std::string suffix : {".out", ".err"}) {
      if (FILE* f = std::fopen((dir_ + "/" + name + suffix).c_str(), "r")) {
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
    for (const char* name : {"child", "listener"}) {
      std::remove((dir_ + "/" + name + ".out").c_str());
      std::remove((dir_ + "/" + name + ".err").c_str());
    }
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
  // The positive control: a listener on the writer's own tag and our domain hears the writer in
  // the same window, so that silence on our tag means the tag parted them, not that the writer
  // never wrote, wrote elsewhere or was slow.
  const auto listener = StartChildMode(testing::kChildReaderFlag, other_tag, "w-other", "listener");
  ASSERT_TRUE(WaitFor([&] { return ChildOutput("listener").find("ready") != std::string::npos; }))
      << ChildOutput("listener");
  child_ = StartChildMode(testing::kChildWriterFlag, other_tag, "w-other", "child");
  const auto seen_on_our_tag = [&](const auto& r) { return r.data.worker_id == "w-other"; };
  bool seen = false;
  EXPECT_TRUE(WaitFor(
      [&] {
        seen = seen || AwaitSample(reader_, seen_on_our_tag, 0.0).has_value();
        return listener->Poll();
      },
      30.0));
  ASSERT_TRUE(listener->exit_status().exited && listener->exit_status().code == 0)
      << "the listener on the writer's tag heard nothing: " << ChildOutput("listener")
      << ChildOutput();
  // The writer's own tag heard it; ours, until then and for 1.5 s more, did not.
  seen = seen || AwaitSample(reader_, seen_on_our_tag, 1.5).has_value();
  EXPECT_FALSE(seen) << "a participant with another tag was discovered";
  EXPECT_EQ(reader_.MatchedWriters(), 0);
  EXPECT_FALSE(child_->Poll()) << ChildOutput();
}

}  // namespace
}  // namespace rlpos
