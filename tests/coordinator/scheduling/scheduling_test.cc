#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "coordinator/scheduling/assignment.h"
#include "coordinator/scheduling/scheduler.h"
#include "coordinator/scheduling/timeouts.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

ReadyJob Ready(const std::string& campaign, const std::string& key, JobKind kind = JobKind::kEval) {
  ReadyJob job;
  job.id = campaign + "/" + key;
  job.campaign_id = campaign;
  job.key = key;
  job.params.kind = kind;
  return job;
}

std::vector<ReadyJob> Evals(const std::string& campaign, int n) {
  std::vector<ReadyJob> jobs;
  for (int i = 0; i < n; ++i)
    jobs.push_back(Ready(campaign, "eval/B/rl/run" + std::to_string(i)));
  return jobs;
}

std::vector<std::string> Workers(const std::vector<Assignment>& assignments) {
  std::vector<std::string> out;
  for (const auto& a : assignments)
    out.push_back(a.worker_id);
  return out;
}

std::vector<std::string> Keys(const std::vector<Assignment>& assignments) {
  std::vector<std::string> out;
  for (const auto& a : assignments)
    out.push_back(a.job.campaign_id + ":" + a.job.key);
  return out;
}

TEST(Assignment, RespectsSlotsAndSpreads) {
  const auto out = AssignJobs(Evals("c", 10), {{"b", 3, 0}, {"a", 2, 1}});
  // Most free slots first, ties to the lower id: b(3) b(2) a(1)=b(1) -> a, then b.
  EXPECT_EQ(Workers(out), (std::vector<std::string>{"b", "b", "a", "b"}));
  EXPECT_EQ(out[0].job.key, "eval/B/rl/run0");
  EXPECT_EQ(out[3].job.key, "eval/B/rl/run3");
}

TEST(Assignment, NothingWithoutFreeSlotsOrJobs) {
  EXPECT_TRUE(AssignJobs(Evals("c", 3), {}).empty());
  EXPECT_TRUE(AssignJobs(Evals("c", 3), {{"a", 2, 2}, {"b", 1, 5}}).empty());
  EXPECT_TRUE(AssignJobs({}, {{"a", 4, 0}}).empty());
  EXPECT_EQ(AssignJobs(Evals("c", 2), {{"a", 4, 0}}).size(), 2u);
}

TEST(Assignment, DeterministicWhateverTheWorkerOrder) {
  const auto jobs = Evals("c", 7);
  const auto a = AssignJobs(jobs, {{"w1", 2, 0}, {"w2", 2, 0}, {"w3", 2, 1}});
  const auto b = AssignJobs(jobs, {{"w3", 2, 1}, {"w2", 2, 0}, {"w1", 2, 0}});
  EXPECT_EQ(Workers(a), Workers(b));
  EXPECT_EQ(Keys(a), Keys(b));
  EXPECT_EQ(Workers(a), (std::vector<std::string>{"w1", "w2", "w1", "w2", "w3"}));
}

TEST(Assignment, DuplicateWorkerCountsOnce) {
  EXPECT_EQ(AssignJobs(Evals("c", 5), {{"a", 2, 0}, {"a", 2, 0}}).size(), 2u);
}

TEST(Assignment, TrainingFirstWithinACampaign) {
  const std::vector<ReadyJob> jobs{
      Ready("c", "eval/B/baseline/run1"), Ready("c", "position/B/oracle", JobKind::kPosition),
      Ready("c", "train/B/seed1", JobKind::kTrain), Ready("c", "eval/B/baseline/run2")};
  EXPECT_EQ(Keys(AssignJobs(jobs, {{"a", 3, 0}})),
            (std::vector<std::string>{"c:train/B/seed1", "c:position/B/oracle",
                                      "c:eval/B/baseline/run1"}));
}

TEST(Assignment, FairBetweenCampaigns) {
  std::vector<ReadyJob> jobs = Evals("old", 5);
  const auto young = Evals("young", 5);
  jobs.insert(jobs.end(), young.begin(), young.end());
  // "old" already runs 3 jobs: "young" catches up first, then they alternate.
  const auto out = AssignJobs(jobs, {{"a", 6, 0}}, {{"old", 3}});
  std::vector<std::string> campaigns;
  for (const auto& a : out)
    campaigns.push_back(a.job.campaign_id);
  EXPECT_EQ(campaigns,
            (std::vector<std::string>{"young", "young", "young", "old", "young", "old"}));
  // With nothing running, the older campaign (listed first) goes first, then they alternate.
  const auto even = AssignJobs(jobs, {{"a", 4, 0}});
  campaigns.clear();
  for (const auto& a : even)
    campaigns.push_back(a.job.campaign_id);
  EXPECT_EQ(campaigns, (std::vector<std::string>{"old", "young", "old", "young"}));
}

TEST(Timeouts, OnlyPastTheirTimeout) {
  const std::vector<RunningJob> running{{"c/a", "c", "w1", 0, 1, 0.0, 600.0},
                                        {"c/b", "c", "w2", 0, 2, 100.0, 600.0},
                                        {"c/c", "c", "w2", 1, 1, 640.0, 5.0}};
  EXPECT_TRUE(FindTimedOut(running, 600.0).empty());  // exactly at the limit: still fine
  const auto late = FindTimedOut(running, 650.5);
  ASSERT_EQ(late.size(), 2u);
  EXPECT_EQ(late[0].job.id, "c/a");
  EXPECT_EQ(late[0].error, "timed out after 600 s");
  EXPECT_EQ(late[1].job.id, "c/c");
  EXPECT_EQ(late[1].error, "timed out after 5 s");
  EXPECT_EQ(TimeoutMessage(0.5), "timed out after 0.5 s");
}

class SchedulerTest : public ::testing::Test {
 protected:
  SchedulerTest() : campaign_(testing::MiniCampaign()), store_(dir_.File("s.db"), Options()) {
    store_.ledger.Submit(campaign_);
  }
  StoreOptions Options() {
    StoreOptions options;
    options.clock = [this] { return now_; };
    return options;
  }
  static std::map<std::string, int> PerWorker(const std::vector<Assignment>& assignments) {
    std::map<std::string, int> out;
    for (const auto& a : assignments)
      ++out[a.worker_id];
    return out;
  }

  testing::TempDir dir_;
  double now_ = 0.0;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
  Scheduler scheduler_{store_.ledger};
};

TEST_F(SchedulerTest, AssignsMarksRunningAndRespectsTheStoresCount) {
  const TickResult first = scheduler_.Tick({{"w1", 2, 0}, {"w2", 1, 0}}, now_);
  EXPECT_TRUE(first.timed_out.empty());
  ASSERT_EQ(first.assigned.size(), 3u);
  EXPECT_EQ(PerWorker(first.assigned), (std::map<std::string, int>{{"w1", 2}, {"w2", 1}}));
  EXPECT_EQ(first.assigned[0].job.params.kind, JobKind::kTrain);
  EXPECT_EQ(store_.ledger.ListRunning().size(), 3u);
  EXPECT_EQ(store_.reader.GetJob(first.assigned[0].job.id)->state, "running");
  // The workers report idle, but the store knows they are full.
  EXPECT_TRUE(scheduler_.Tick({{"w1", 2, 0}, {"w2", 1, 0}}, now_).assigned.empty());
  // A new worker gets work.
  EXPECT_EQ(scheduler_.Tick({{"w1", 2, 0}, {"w2", 1, 0}, {"w3", 4, 0}}, now_).assigned.size(), 4u);
}

TEST_F(SchedulerTest, EachJobGetsTheLowestFreeSlotOfItsWorker) {
  const TickResult first = scheduler_.Tick({{"w1", 3, 0}, {"w2", 1, 0}}, now_);
  std::map<std::string, std::vector<int>> slots;
  for (const auto& a : first.assigned)
    slots[a.worker_id].push_back(a.slot);
  EXPECT_EQ(slots, (std::map<std::string, std::vector<int>>{{"w1", {0, 1, 2}}, {"w2", {0}}}));
  const auto middle =
      std::find_if(first.assigned.begin(), first.assigned.end(),
                   [](const Assignment& a) { return a.worker_id == "w1" && a.slot == 1; });
  ASSERT_NE(middle, first.assigned.end());
  EXPECT_EQ(store_.reader.GetJob(middle->job.id)->slot, 1);
  // Slot 1 frees: the next job goes there, and w1's other slots stay as they are.
  ASSERT_EQ(store_.ledger.RecordFailure(middle->job.id, middle->job.attempt, "boom"),
            JobUpdate::kRetrying);
  const TickResult next = scheduler_.Tick({{"w1", 3, 0}, {"w2", 1, 0}}, now_);
  ASSERT_EQ(next.assigned.size(), 1u);
  EXPECT_EQ(next.assigned[0].worker_id, "w1");
  EXPECT_EQ(next.assigned[0].slot, 1);
}

TEST_F(SchedulerTest, TimedOutJobsFailAndAreReassigned) {
  const TickResult first = scheduler_.Tick({{"w1", 2, 0}}, now_);
  ASSERT_EQ(first.assigned.size(), 2u);
  now_ = 301.0;  // mini: job_timeout_s 300
  const TickResult later = scheduler_.Tick({{"w1", 2, 0}}, now_);
  ASSERT_EQ(later.timed_out.size(), 2u);
  EXPECT_EQ(later.timed_out[0].job.worker_id, "w1");
  EXPECT_EQ(later.timed_out[0].error, "timed out after 300 s");
  // The same two jobs, next attempt, on the slots the timeouts freed.
  ASSERT_EQ(later.assigned.size(), 2u);
  EXPECT_EQ(later.assigned[0].job.id, first.assigned[0].job.id);
  EXPECT_EQ(later.assigned[0].job.attempt, 2);
  EXPECT_EQ(store_.reader.GetJob(later.assigned[0].job.id)->error, "timed out after 300 s");
  // The first attempt's result, arriving now, is stale.
  EXPECT_EQ(
      store_.recorder.RecordSuccess(first.assigned[0].job.id, 1, testing::PositionResult(1, 1, 9)),
      JobUpdate::kStale);
}

TEST_F(SchedulerTest, LostWorkersJobsGoToTheOthers) {
  const TickResult first = scheduler_.Tick({{"w1", 2, 0}, {"w2", 2, 0}}, now_);
  ASSERT_EQ(first.assigned.size(), 4u);
  const auto lost = scheduler_.WorkerLost("w1");
  ASSERT_EQ(lost.size(), 2u);
  const TickResult next = scheduler_.Tick({{"w2", 4, 0}}, now_);
  ASSERT_EQ(next.assigned.size(), 2u);  // w2 runs 2 already
  for (const auto& a : next.assigned) {
    EXPECT_EQ(a.worker_id, "w2");
    EXPECT_NE(std::find(lost.begin(), lost.end(), a.job.id), lost.end()) << a.job.id;
    EXPECT_EQ(a.job.attempt, 2);
  }
}

TEST_F(SchedulerTest, RunsAMiniCampaignToTheEnd) {
  int ticks = 0;
  while (store_.reader.Progress(campaign_.id).state == "active" && ticks < 100) {
    ++ticks;
    for (const auto& a : scheduler_.Tick({{"w1", 3, 0}, {"w2", 2, 0}}, now_).assigned) {
      const JobRecord job = *store_.reader.GetJob(a.job.id);
      const auto result =
          a.job.params.kind == JobKind::kEval
              ? testing::EvalResult(static_cast<std::uint64_t>(*job.params.rng_run), 90, 2)
              : testing::PositionResult(50, 35, 10);
      ASSERT_EQ(
          store_.recorder.RecordSuccess(a.job.id, a.job.attempt,
                                        testing::AtJobPosition(store_.reader, a.job.id, result)),
          JobUpdate::kSucceeded);
    }
  }
  EXPECT_EQ(store_.reader.Progress(campaign_.id).state, "finished");
  EXPECT_EQ(store_.reader.Metrics(campaign_.id).size(), 36u);
  EXPECT_EQ(ticks, 9);  // 44 jobs on 5 slots, never idle: producers free evals in time
}

// The binding rule refuses what it cannot bind: offset evals are defined around one UAV, so a
// producer with offset dependants that reports several UAVs fails that attempt, and nothing of
// the result is written.
TEST_F(SchedulerTest, APlacementOfSeveralUavsCannotFeedOffsetEvals) {
  const std::string train = campaign_.id + "/train/B/seed1";
  ASSERT_TRUE(store_.ledger.MarkRunning(train, "w1", 0, 1));
  nlohmann::json result = testing::PositionResult(50, 35, 10);
  result["positions"] = {{50, 35, 10}, {20, 20, 10}};
  EXPECT_EQ(store_.recorder.RecordSuccess(train, 1, result, "w1"), JobUpdate::kRetrying);
  const JobRecord job = *store_.reader.GetJob(train);
  EXPECT_EQ(job.state, "ready");
  EXPECT_EQ(job.error.value_or(""),
            "malformed result: a placement of 2 UAVs, but offset evals (defined for one) depend "
            "on it");
  EXPECT_FALSE(job.result.has_value());
  EXPECT_FALSE(store_.reader.GetJob(campaign_.id + "/eval/B/offset1/run1")->placement);
}

}  // namespace
}  // namespace rlpos
