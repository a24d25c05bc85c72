// rlpos-worker against a scripted coordinator: assignments are per slot, and the slot's
// content is what the worker runs. A stand-in simulator that prints one progress line and then
// waits keeps each job running until the worker stops it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "common/process/child_process.h"
#include "idl/dds/dds_config.h"
#include "idl/dds/topics.h"
#include "tests/idl/dds/dds_test_support.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

using testing::AwaitSample;
using testing::WaitFor;

constexpr int kSlots = 2;

class WorkerSlotsTest : public ::testing::Test {
 protected:
  WorkerSlotsTest()
      : options_(testing::TestOptions()),
        participant_(options_),
        assignments_(participant_),
        events_(participant_),
        statuses_(participant_) {}

  void SetUp() override {
    testing::WriteFile(dir_.File("sim.sh"), "#!/bin/sh\necho working >&2\nexec sleep 60\n");
    ASSERT_EQ(::chmod(dir_.File("sim.sh").c_str(), 0755), 0);
    worker_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{std::string(RLPOS_BIN_DIR) + "/rlpos-worker", "--id", "w",
                                 "--slots", std::to_string(kSlots), "--work-dir", dir_.File("work"),
                                 "--sim", dir_.File("sim.sh"), "--loopback", options_.loopback_tag,
                                 "--domain", std::to_string(options_.domain), "--log-level",
                                 "info"},
        dir_.File("worker.out"), dir_.File("worker.err"));
    ASSERT_TRUE(AwaitSample(
        statuses_, [](const auto& r) { return r.valid && r.data.worker_id == "w"; }, 20.0))
        << testing::ReadFile(dir_.File("worker.err"));
    ASSERT_TRUE(WaitFor([&] { return assignments_.MatchedReaders() >= 1; }));
  }
  void TearDown() override { worker_.reset(); }

  static msg::JobAssignment Job(const std::string& name, int slot) {
    msg::JobAssignment a;
    a.worker_id = "w";
    a.slot = slot;
    JobOrder& o = a.order;
    o.job_id = "0123456789ab/eval/B/" + name + "/run1";
    o.campaign_id = "0123456789ab";
    o.attempt = 1;
    o.timeout_s = 120;
    o.params.kind = JobKind::kEval;
    o.params.scenario = "B";
    o.params.rng_run = 1;
    o.placement = Placement{{50, 35, 30}};
    o.scenario_document =
        testing::ReadFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json");
    return a;
  }

  // True once the worker reported the progress of each of `jobs` from its slot (in any order:
  // each job reports its progress line once).
  bool AwaitProgress(const std::vector<msg::JobAssignment>& jobs) {
    std::vector<bool> seen(jobs.size(), false);
    return AwaitSample(
               events_,
               [&](const auto& r) {
                 for (std::size_t i = 0; i < jobs.size(); ++i) {
                   seen[i] = seen[i] ||
                             (r.valid && r.data.state == msg::JobState::kProgress &&
                              r.data.slot == jobs[i].slot && r.data.job_id == jobs[i].order.job_id);
                 }
                 return std::all_of(seen.begin(), seen.end(), [](bool b) { return b; });
               },
               20.0)
        .has_value();
  }

  // True once the worker's status lists exactly `jobs` ("<job id>#<attempt>", any order). A
  // status goes out when a job stops, not when one starts.
  bool AwaitRunning(std::vector<std::string> jobs) {
    std::sort(jobs.begin(), jobs.end());
    return AwaitSample(
               statuses_,
               [&](const auto& r) {
                 auto listed = r.data.jobs;
                 std::sort(listed.begin(), listed.end());
                 return r.valid && r.data.worker_id == "w" && listed == jobs;
               },
               20.0)
        .has_value();
  }

  testing::TempDir dir_;
  DdsOptions options_;
  Participant participant_;
  Writer<msg::JobAssignment> assignments_;
  Reader<msg::JobEvent> events_;
  Reader<msg::WorkerStatus> statuses_;
  std::unique_ptr<ChildProcess> worker_;
};

TEST_F(WorkerSlotsTest, ASlotGivenAnotherJobStopsTheOldOne) {
  const auto first = Job("first", 0), second = Job("second", 0);
  assignments_.Write(first);
  ASSERT_TRUE(AwaitProgress({first})) << testing::ReadFile(dir_.File("worker.err"));
  assignments_.Write(second);
  ASSERT_TRUE(AwaitProgress({second})) << testing::ReadFile(dir_.File("worker.err"));
  EXPECT_TRUE(AwaitRunning({second.order.job_id + "#1"}))
      << testing::ReadFile(dir_.File("worker.err"));
}

TEST_F(WorkerSlotsTest, AnEmptiedSlotStopsItsJobAndDisposesItsEvent) {
  const auto kept = Job("kept", 0), withdrawn = Job("withdrawn", 1);
  assignments_.Write(kept);
  assignments_.Write(withdrawn);
  ASSERT_TRUE(AwaitProgress({kept, withdrawn})) << testing::ReadFile(dir_.File("worker.err"));
  msg::JobAssignment key;
  key.worker_id = "w";
  key.slot = 1;
  assignments_.Dispose(key);
  const auto disposed = AwaitSample(
      events_,
      [](const auto& r) {
        return !r.valid && r.state == InstanceState::kDisposed && r.data.worker_id == "w" &&
               r.data.slot == 1;
      },
      20.0);
  EXPECT_TRUE(disposed.has_value()) << testing::ReadFile(dir_.File("worker.err"));
  EXPECT_TRUE(AwaitRunning({kept.order.job_id + "#1"}));
}

TEST_F(WorkerSlotsTest, ASlotItDoesNotHaveIsDropped) {
  const auto outside = Job("outside", kSlots), inside = Job("inside", 1);
  assignments_.Write(outside);
  assignments_.Write(inside);  // after it: once this one runs, the other was seen
  ASSERT_TRUE(AwaitProgress({inside})) << testing::ReadFile(dir_.File("worker.err"));
  EXPECT_NE(testing::ReadFile(dir_.File("worker.err")).find("slot 2 is not one of this worker's 2"),
            std::string::npos)
      << testing::ReadFile(dir_.File("worker.err"));
}

}  // namespace
}  // namespace rlpos
