// What `status` and `run` read from the store while a campaign runs: workers, timings, failed
// jobs, running jobs and their progress lines.
#include <gtest/gtest.h>

#include "common/store/store_error.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using testing::PositionResult;

class MonitoringTest : public ::testing::Test {
 protected:
  MonitoringTest() : campaign_(testing::MiniCampaign()), store_(dir_.File("rlpos.db"), Options()) {}

  StoreOptions Options() {
    StoreOptions options;
    options.clock = [this] { return now_; };
    return options;
  }
  std::string Id(const std::string& key) const { return campaign_.id + "/" + key; }
  static WorkerRecord Worker(const std::string& id, int slots, int busy) {
    WorkerRecord w;
    w.id = id;
    w.host = "host-" + id;
    w.pid = 4000 + slots;
    w.slots = slots;
    w.busy = busy;
    return w;
  }
  const WorkerRecord* Find(const std::vector<WorkerRecord>& workers, const std::string& id) {
    for (const auto& w : workers) {
      if (w.id == id)
        return &w;
    }
    ADD_FAILURE() << "no worker " << id;
    return nullptr;
  }
  static std::vector<std::string> Ids(const std::vector<WorkerRecord>& workers) {
    std::vector<std::string> ids;
    for (const auto& w : workers)
      ids.push_back(w.id);
    return ids;
  }

  testing::TempDir dir_;
  double now_ = 1000.0;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

TEST_F(MonitoringTest, UpsertWorkerKeepsFirstSeenAndRefreshesTheRest) {
  EXPECT_TRUE(store_.reader.ListWorkers().empty());
  store_.ledger.UpsertWorker(Worker("w2", 4, 1));
  now_ = 1010;
  store_.ledger.UpsertWorker(Worker("w1", 2, 0));
  now_ = 1020;
  WorkerRecord again = Worker("w2", 4, 3);
  again.host = "elsewhere";
  again.pid = 99;
  store_.ledger.UpsertWorker(again);

  const auto workers = store_.reader.ListWorkers();
  ASSERT_EQ(Ids(workers), (std::vector<std::string>{"w1", "w2"}));
  const WorkerRecord& w1 = workers[0];
  EXPECT_EQ(w1.host, "host-w1");
  EXPECT_EQ(w1.pid, 4002);
  EXPECT_EQ(w1.slots, 2);
  EXPECT_EQ(w1.busy, 0);
  EXPECT_EQ(w1.state, "alive");
  EXPECT_DOUBLE_EQ(w1.first_seen, 1010);
  EXPECT_DOUBLE_EQ(w1.last_seen, 1010);
  const WorkerRecord& w2 = workers[1];
  EXPECT_EQ(w2.host, "elsewhere");
  EXPECT_EQ(w2.pid, 99);
  EXPECT_EQ(w2.slots, 4);
  EXPECT_EQ(w2.busy, 3);
  EXPECT_DOUBLE_EQ(w2.first_seen, 1000);
  EXPECT_DOUBLE_EQ(w2.last_seen, 1020);
}

TEST_F(MonitoringTest, WorkerStatesAndListOrder) {
  store_.ledger.UpsertWorker(Worker("a", 1, 1));
  store_.ledger.UpsertWorker(Worker("b", 2, 2));
  store_.ledger.UpsertWorker(Worker("c", 3, 1));
  store_.ledger.UpsertWorker(Worker("d", 4, 0));
  now_ = 1100;
  store_.ledger.SetWorkerState("a", "lost");
  store_.ledger.SetWorkerState("c", "stopped");
  store_.ledger.SetWorkerState("nobody", "lost");  // no-op

  auto workers = store_.reader.ListWorkers();
  // Alive first, then the others, each group by id.
  EXPECT_EQ(Ids(workers), (std::vector<std::string>{"b", "d", "a", "c"}));
  if (const auto* a = Find(workers, "a")) {
    EXPECT_EQ(a->state, "lost");
    EXPECT_EQ(a->busy, 0);
    EXPECT_DOUBLE_EQ(a->last_seen, 1100);
    EXPECT_DOUBLE_EQ(a->first_seen, 1000);
  }
  if (const auto* c = Find(workers, "c")) {
    EXPECT_EQ(c->state, "stopped");
  }
  EXPECT_THROW(store_.ledger.SetWorkerState("b", "zombie"), StoreError);  // CHECK constraint

  // A lost worker that shows up again is alive.
  now_ = 1200;
  store_.ledger.UpsertWorker(Worker("a", 1, 1));
  workers = store_.reader.ListWorkers();
  EXPECT_EQ(Ids(workers), (std::vector<std::string>{"a", "b", "d", "c"}));

  // The coordinator's start: every alive worker is lost (busy 0, last_seen kept); stopped stays.
  now_ = 1300;
  store_.ledger.MarkAllWorkersLost();
  workers = store_.reader.ListWorkers();
  EXPECT_EQ(Ids(workers), (std::vector<std::string>{"a", "b", "c", "d"}));
  for (const auto& w : workers) {
    SCOPED_TRACE(w.id);
    EXPECT_EQ(w.state, w.id == "c" ? "stopped" : "lost");
    EXPECT_EQ(w.busy, 0);
    EXPECT_LT(w.last_seen, 1300);
  }
  if (const auto* a = Find(workers, "a")) {
    EXPECT_DOUBLE_EQ(a->last_seen, 1200);
  }
}

TEST_F(MonitoringTest, UnknownCampaignThrows) {
  store_.ledger.Submit(campaign_);
  EXPECT_THROW(store_.reader.Timing("nope"), StoreError);
  EXPECT_THROW(store_.reader.FailedJobs("nope"), StoreError);
  EXPECT_THROW(store_.reader.RunningJobs("nope"), StoreError);
  EXPECT_FALSE(store_.reader.CampaignSpecPart("nope", "scenarios").has_value());
  for (const std::string key : {"scenarios", "name", "rng_runs", "retries"}) {
    const auto part = store_.reader.CampaignSpecPart(campaign_.id, key);
    ASSERT_TRUE(part.has_value()) << key;
    EXPECT_EQ(*part, nlohmann::json({{key, nlohmann::json::parse(campaign_.spec_json).at(key)}}))
        << key;
  }
  EXPECT_EQ(store_.reader.CampaignSpecPart(campaign_.id, "nosuchkey"), nlohmann::json::object());
}

TEST_F(MonitoringTest, TimingFollowsStartsAndFinishes) {
  store_.ledger.Submit(campaign_);
  CampaignTiming t = store_.reader.Timing(campaign_.id);
  EXPECT_DOUBLE_EQ(t.created_at, 1000);
  EXPECT_FALSE(t.first_started_at.has_value());
  EXPECT_FALSE(t.last_finished_at.has_value());
  EXPECT_EQ(t.finished, 0);

  now_ = 1010;
  ASSERT_TRUE(store_.ledger.MarkRunning(Id("position/B/centroid"), "w1", 0, 1));
  now_ = 1025;
  ASSERT_TRUE(store_.ledger.MarkRunning(Id("position/C/oracle"), "w1", 0, 1));
  t = store_.reader.Timing(campaign_.id);
  ASSERT_TRUE(t.first_started_at.has_value());
  EXPECT_DOUBLE_EQ(*t.first_started_at, 1010);
  EXPECT_FALSE(t.last_finished_at.has_value());
  EXPECT_EQ(t.finished, 0);

  now_ = 1040;
  ASSERT_EQ(store_.recorder.RecordSuccess(Id("position/C/oracle"), 1, PositionResult(50, 50, 30)),
            JobUpdate::kSucceeded);
  now_ = 1060;
  ASSERT_EQ(store_.recorder.RecordSuccess(Id("position/B/centroid"), 1, PositionResult(40, 40, 25)),
            JobUpdate::kSucceeded);
  t = store_.reader.Timing(campaign_.id);
  EXPECT_DOUBLE_EQ(t.created_at, 1000);
  EXPECT_DOUBLE_EQ(*t.first_started_at, 1010);
  ASSERT_TRUE(t.last_finished_at.has_value());
  EXPECT_DOUBLE_EQ(*t.last_finished_at, 1060);
  EXPECT_EQ(t.finished, 2);

  now_ = 1100;
  store_.ledger.CancelCampaign(campaign_.id);
  t = store_.reader.Timing(campaign_.id);
  EXPECT_EQ(t.finished, 44);  // 2 succeeded, 42 cancelled
  EXPECT_DOUBLE_EQ(*t.last_finished_at, 1100);
}

TEST_F(MonitoringTest, FailedJobsListExhaustedJobsAndTheirDependents) {
  store_.ledger.Submit(campaign_);
  EXPECT_TRUE(store_.reader.FailedJobs(campaign_.id).empty());
  const std::string train = Id("train/B/seed1");
  ASSERT_TRUE(store_.ledger.MarkRunning(train, "w1", 0, 1));
  ASSERT_EQ(store_.ledger.RecordFailure(train, 1, "first crash"), JobUpdate::kRetrying);
  EXPECT_TRUE(store_.reader.FailedJobs(campaign_.id).empty());  // retrying is not failed
  ASSERT_TRUE(store_.ledger.MarkRunning(train, "w1", 0, 2));
  ASSERT_EQ(store_.ledger.RecordFailure(train, 2, "second crash"), JobUpdate::kFailed);

  const auto failed = store_.reader.FailedJobs(campaign_.id);
  // The train job, then its 12 evals (rl and offset1..5, runs 1 and 2) in expansion order.
  ASSERT_EQ(failed.size(), 13u);
  EXPECT_EQ(failed[0].key, "train/B/seed1");
  EXPECT_EQ(failed[0].attempts, 2);
  EXPECT_EQ(failed[0].error, "second crash");
  std::size_t previous_seq = 0;
  for (std::size_t i = 1; i < failed.size(); ++i) {
    SCOPED_TRACE(failed[i].key);
    EXPECT_EQ(failed[i].key.rfind("eval/B/", 0), 0u);
    EXPECT_EQ(failed[i].attempts, 1);
    EXPECT_EQ(failed[i].error, "dependency " + train + " failed");
    std::size_t seq = 0;
    while (seq < campaign_.jobs.size() && campaign_.jobs[seq].key != failed[i].key)
      ++seq;
    ASSERT_LT(seq, campaign_.jobs.size());
    EXPECT_GT(seq, previous_seq);
    previous_seq = seq;
  }
  EXPECT_EQ(store_.reader.Timing(campaign_.id).finished, 13);
}

TEST_F(MonitoringTest, RunningJobsShowWorkerAttemptAndProgress) {
  store_.ledger.Submit(campaign_);
  now_ = 1005;
  ASSERT_TRUE(store_.ledger.MarkRunning(Id("position/B/oracle"), "w7", 0, 1));
  now_ = 1007;
  ASSERT_TRUE(store_.ledger.MarkRunning(Id("train/C/seed1"), "w8", 0, 1));
  store_.ledger.SetProgress(Id("train/C/seed1"), 1, "episode 3/10");
  store_.ledger.SetProgress(Id("train/C/seed1"), 2, "stale attempt");  // ignored
  store_.ledger.SetProgress(Id("train/B/seed1"), 1, "not running");    // ignored

  const auto running = store_.reader.RunningJobs(campaign_.id);
  ASSERT_EQ(running.size(), 2u);
  EXPECT_EQ(running[0].key, "position/B/oracle");
  EXPECT_EQ(running[0].worker_id, "w7");
  EXPECT_EQ(running[0].attempt, 1);
  EXPECT_DOUBLE_EQ(running[0].started_at, 1005);
  EXPECT_EQ(running[0].progress, "");
  EXPECT_EQ(running[1].key, "train/C/seed1");
  EXPECT_EQ(running[1].worker_id, "w8");
  EXPECT_DOUBLE_EQ(running[1].started_at, 1007);
  EXPECT_EQ(running[1].progress, "episode 3/10");
}

TEST_F(MonitoringTest, ReadyJobsCarryTheirScenarioName) {
  store_.ledger.Submit(campaign_);
  const auto ready = store_.ledger.ListReady();
  ASSERT_FALSE(ready.empty());
  int b = 0, c = 0;
  for (const auto& job : ready) {
    SCOPED_TRACE(job.key);
    // The key's second component is the scenario: train/B/seed1, position/C/oracle.
    const auto first = job.key.find('/');
    const auto second = job.key.find('/', first + 1);
    EXPECT_EQ(job.params.scenario, job.key.substr(first + 1, second - first - 1));
    b += job.params.scenario == "B";
    c += job.params.scenario == "C";
  }
  EXPECT_GT(b, 0);
  EXPECT_GT(c, 0);
  EXPECT_EQ(ready[0].key, "train/B/seed1");  // trains first, then expansion order
  EXPECT_EQ(ready[0].params.scenario, "B");
}

}  // namespace
}  // namespace rlpos
