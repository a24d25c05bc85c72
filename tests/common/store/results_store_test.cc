#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "common/hash/sha256.h"
#include "common/scenario/number_text.h"
#include "common/store/artifact_files.h"
#include "common/store/store_error.h"
#include "common/wire/limits.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;
using testing::AtJobPosition;
using testing::EvalResult;
using testing::FindJob;
using testing::PositionResult;

// A store on a temp file with a clock the test moves.
class StoreTest : public ::testing::Test {
 protected:
  StoreTest() : campaign_(testing::MiniCampaign()), store_(dir_.File("rlpos.db"), Options()) {}

  StoreOptions Options() {
    StoreOptions options;
    options.clock = [this] { return now_; };
    return options;
  }
  std::string Id(const std::string& key) const { return campaign_.id + "/" + key; }
  JobRecord Job(const std::string& key) {
    const auto job = store_.reader.GetJob(Id(key));
    if (!job)
      throw std::out_of_range("no job " + key);
    return *job;
  }
  // Runs a job's current attempt on `worker` and returns that attempt.
  int Start(const std::string& key, const std::string& worker = "w1") {
    const int attempt = Job(key).attempt;
    EXPECT_TRUE(store_.ledger.MarkRunning(Id(key), worker, 0, attempt)) << key;
    return attempt;
  }
  // One value from SQL, through the C API (what a user's own query sees).
  std::string Query(const std::string& sql) {
    return testing::QueryOne(dir_.File("rlpos.db"), sql);
  }

  testing::TempDir dir_;
  double now_ = 1000.0;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

TEST_F(StoreTest, SubmitIsIdempotent) {
  const SubmitResult first = store_.ledger.Submit(campaign_);
  EXPECT_TRUE(first.created);
  EXPECT_EQ(first.campaign_id, campaign_.id);
  EXPECT_EQ(first.jobs, 44);
  now_ += 50;
  const SubmitResult again = store_.ledger.Submit(testing::MiniCampaign());
  EXPECT_FALSE(again.created);
  EXPECT_EQ(again.campaign_id, campaign_.id);
  EXPECT_EQ(again.jobs, 44);
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs"), "44");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM campaigns"), "1");
  EXPECT_EQ(Query("SELECT created_at FROM campaigns"), "1000.0");
}

TEST_F(StoreTest, ProducersStartReadyEvalsPending) {
  store_.ledger.Submit(campaign_);
  const CampaignProgress p = store_.reader.Progress(campaign_.id);
  EXPECT_EQ(p.name, "mini");
  EXPECT_EQ(p.state, "active");
  EXPECT_EQ(p.total, 44);
  EXPECT_EQ(p.ready, 8);  // 2 scenarios x (train + 3 positions)
  EXPECT_EQ(p.pending, 36);
  const auto ready = store_.ledger.ListReady();
  ASSERT_EQ(ready.size(), 8u);
  // Trains first, then positions in expansion order: B's, then C's.
  EXPECT_EQ(ready[0].id, Id("train/B/seed1"));
  EXPECT_EQ(ready[1].id, Id("train/C/seed1"));
  EXPECT_EQ(ready[2].id, Id("position/B/baseline"));
  const ReadyJob& position = ready[2];
  EXPECT_EQ(position.attempt, 1);
  EXPECT_DOUBLE_EQ(position.timeout_s, 300.0);
  const rlpos::Job& expected = FindJob(campaign_, "position/B/baseline");
  EXPECT_EQ(position.params.kind, JobKind::kPosition);
  EXPECT_EQ(position.params.positioner, "baseline");
  EXPECT_EQ(position.params.scenario, expected.params.scenario);
  EXPECT_EQ(position.params.duration_s, expected.params.duration_s);
  EXPECT_EQ(position.params.warmup_s, expected.params.warmup_s);
  EXPECT_EQ(position.params.overrides, expected.params.overrides);
  EXPECT_FALSE(position.placement.has_value());
  EXPECT_EQ(store_.ledger.ListReady(3).size(), 3u);
}

TEST_F(StoreTest, ProducerSuccessBindsPositionsOfItsEvals) {
  store_.ledger.Submit(campaign_);
  const int attempt = Start("train/B/seed1");
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("train/B/seed1"), attempt, PositionResult(50, 35, 10)),
            JobUpdate::kSucceeded);
  const auto position_of = [this](const std::string& key) {
    return testing::FormatPlacement(Job(key).placement);
  };
  EXPECT_EQ(Job("eval/B/rl/run1").state, "ready");
  EXPECT_EQ(position_of("eval/B/rl/run1"), "50,35,10");
  EXPECT_EQ(position_of("eval/B/offset1/run2"), "60,35,10");
  EXPECT_EQ(position_of("eval/B/offset3/run1"), "50,44.5,10");  // stops before the tower
  EXPECT_EQ(position_of("eval/B/offset5/run1"), "50,35,20");
  // Other scenarios and positioners still wait.
  EXPECT_EQ(Job("eval/C/rl/run1").state, "pending");
  EXPECT_EQ(Job("eval/B/baseline/run1").state, "pending");
  EXPECT_EQ(position_of("eval/B/baseline/run1"), "unbound");
  EXPECT_EQ(store_.reader.Progress(campaign_.id).ready, 7 + 2 * 6);
  // What a worker is then ordered: the bound position with the job's typed fields.
  int evals = 0;
  for (const auto& job : store_.ledger.ListReady()) {
    if (job.params.kind != JobKind::kEval)
      continue;
    ++evals;
    ASSERT_TRUE(job.placement.has_value()) << job.key;
    EXPECT_EQ(testing::FormatPlacement(job.placement), position_of(job.key)) << job.key;
    EXPECT_TRUE(testing::SameParams(job.params, FindJob(campaign_, job.key).params)) << job.key;
  }
  EXPECT_EQ(evals, 2 * 6);
}

TEST(StoreDependants, AProducerReleasesMoreDependantsThanOneChunk) {
  testing::TempDir dir;
  CoordinatorStore store(dir.File("s.db"));
  CampaignSpec spec = testing::MiniSpec();
  spec.scenarios.resize(1);  // B
  spec.positioners = {"baseline"};
  spec.rng_runs.clear();
  for (std::uint64_t run = 1; run <= 2500; ++run)  // dependants come 1024 at a time
    spec.rng_runs.push_back(run);
  ExpandedCampaign campaign = ExpandCampaign(spec);
  campaign.use_cache = false;
  store.ledger.Submit(campaign);
  const std::string producer = campaign.id + "/position/B/baseline";
  ASSERT_TRUE(store.ledger.MarkRunning(producer, "w1", 0, 1));
  ASSERT_EQ(store.recorder.RecordSuccess(producer, 1, PositionResult(50, 35, 10)),
            JobUpdate::kSucceeded);
  EXPECT_EQ(store.reader.Progress(campaign.id).ready, 2500);
  EXPECT_EQ(testing::QueryOne(dir.File("s.db"),
                              "SELECT COUNT(*) FROM jobs WHERE kind = 'eval' AND x = 50 AND y = 35 "
                              "AND z = 10 AND cache_key IS NOT NULL AND content_base IS NULL"),
            "2500");
}

TEST_F(StoreTest, EveryTypedFieldSurvivesTheStore) {
  CampaignSpec spec = testing::MiniSpec();
  spec.scenarios[0].overrides = {"wifi.mode=adhoc", "/ues/0/demand=12.5"};
  spec.train.seeds = {4, 9};
  spec.train.fidelity = "packet";
  spec.train.episodes = 25;
  const ExpandedCampaign campaign = ExpandCampaign(spec);
  ASSERT_TRUE(store_.ledger.Submit(campaign).created);
  for (const auto& job : campaign.jobs) {
    SCOPED_TRACE(job.key);
    const auto record = store_.reader.GetJob(job.id);
    ASSERT_TRUE(record.has_value());
    EXPECT_EQ(record->key, job.key);
    EXPECT_EQ(record->label, job.label);
    EXPECT_EQ(record->depends_on, job.depends_on);
    EXPECT_DOUBLE_EQ(record->timeout_s, 300.0);
    EXPECT_TRUE(testing::SameParams(record->params, job.params));
    EXPECT_FALSE(record->placement.has_value());  // nothing bound yet
  }
  const auto ready = store_.ledger.ListReady();
  ASSERT_FALSE(ready.empty());
  for (const auto& job : ready)
    EXPECT_TRUE(testing::SameParams(job.params, FindJob(campaign, job.key).params)) << job.key;
}

TEST_F(StoreTest, OnlyTheWorkerThatHoldsAnAttemptSettlesIt) {
  store_.ledger.Submit(campaign_);
  const std::string job = Id("position/B/baseline");
  const int attempt = Start("position/B/baseline", "w1");
  EXPECT_EQ(store_.recorder.RecordSuccess(job, attempt, PositionResult(50, 50, 25), "w2"),
            JobUpdate::kStale);
  EXPECT_EQ(store_.ledger.RecordFailure(job, attempt, "from another worker", "w2"),
            JobUpdate::kStale);
  store_.ledger.SetProgress(job, attempt, "from another worker", "w2");
  EXPECT_EQ(store_.reader.RunningJobs(campaign_.id).at(0).progress, "");
  EXPECT_EQ(Job("position/B/baseline").state, "running");
  store_.ledger.SetProgress(job, attempt, "scoring", "w1");
  EXPECT_EQ(store_.reader.RunningJobs(campaign_.id).at(0).progress, "scoring");
  EXPECT_EQ(store_.recorder.RecordSuccess(job, attempt, PositionResult(50, 50, 25), "w1"),
            JobUpdate::kSucceeded);

  const std::string other = Id("position/C/baseline");
  const int other_attempt = Start("position/C/baseline", "w1");
  EXPECT_EQ(store_.ledger.RecordFailure(other, other_attempt, "crashed", "w1"),
            JobUpdate::kRetrying);
}

TEST_F(StoreTest, AResultOfAnotherPositionIsAFailedAttempt) {
  store_.ledger.Submit(campaign_);
  Start("position/B/baseline");
  store_.recorder.RecordSuccess(Id("position/B/baseline"), 1, PositionResult(50, 50, 25));
  const std::string eval = Id("eval/B/baseline/run1");
  Start("eval/B/baseline/run1");
  json result = EvalResult(1, 100, 2);
  result["position"] = {50.0, 50.0, 26.0};  // not where the job put the UAV
  EXPECT_EQ(store_.recorder.RecordSuccess(eval, 1, result), JobUpdate::kRetrying);
  EXPECT_EQ(Job("eval/B/baseline/run1").error,
            "malformed result: result is of another placement than the job's");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "0");
  Start("eval/B/baseline/run1");
  result["position"] = {50.0, 50.0, 25.0};
  EXPECT_EQ(store_.recorder.RecordSuccess(eval, 2, result), JobUpdate::kSucceeded);
  EXPECT_EQ(Query("SELECT x || ',' || y || ',' || z FROM metrics"), "50.0,50.0,25.0");
}

TEST_F(StoreTest, StaleAttemptsAreIgnored) {
  store_.ledger.Submit(campaign_);
  const std::string job = Id("position/B/baseline");
  // Not running yet: no result counts.
  EXPECT_EQ(store_.recorder.RecordSuccess(job, 1, PositionResult(50, 50, 25)), JobUpdate::kStale);
  EXPECT_FALSE(store_.ledger.MarkRunning(job, "w1", 0, 2));  // not its attempt
  const int attempt = Start("position/B/baseline");
  EXPECT_FALSE(store_.ledger.MarkRunning(job, "w2", 0, attempt));  // already running
  EXPECT_EQ(store_.recorder.RecordSuccess(job, attempt + 1, PositionResult(50, 50, 25)),
            JobUpdate::kStale);
  EXPECT_EQ(store_.ledger.RecordFailure(job, attempt - 1, "old"), JobUpdate::kStale);
  EXPECT_EQ(Job("position/B/baseline").state, "running");
  EXPECT_EQ(Job("position/B/baseline").worker_id, "w1");
  EXPECT_EQ(store_.recorder.RecordSuccess("nope/x", 1, PositionResult(1, 1, 1)),
            JobUpdate::kUnknown);
  EXPECT_EQ(store_.ledger.RecordFailure("nope/x", 1, "x"), JobUpdate::kUnknown);

  // A result of an attempt that was retried since is stale too.
  EXPECT_EQ(store_.ledger.RecordFailure(job, attempt, "crashed"), JobUpdate::kRetrying);
  EXPECT_EQ(store_.recorder.RecordSuccess(job, attempt, PositionResult(50, 50, 25)),
            JobUpdate::kStale);
  EXPECT_EQ(Job("position/B/baseline").state, "ready");
}

TEST_F(StoreTest, SuccessCountsExactlyOnce) {
  store_.ledger.Submit(campaign_);
  store_.ledger.MarkRunning(Id("position/B/baseline"), "w1", 0, 1);
  store_.recorder.RecordSuccess(Id("position/B/baseline"), 1, PositionResult(50, 50, 25));
  const std::string eval = Id("eval/B/baseline/run2");
  const int attempt = Start("eval/B/baseline/run2");
  EXPECT_EQ(store_.recorder.RecordSuccess(
                eval, attempt, AtJobPosition(store_.reader, eval, EvalResult(2, 120.5, 3.25))),
            JobUpdate::kSucceeded);
  // A duplicate delivery of the same result, a different one, or a late failure: all ignored.
  EXPECT_EQ(store_.recorder.RecordSuccess(
                eval, attempt, AtJobPosition(store_.reader, eval, EvalResult(2, 120.5, 3.25))),
            JobUpdate::kStale);
  EXPECT_EQ(store_.recorder.RecordSuccess(eval, attempt, EvalResult(2, 999.0, 1.0)),
            JobUpdate::kStale);
  EXPECT_EQ(store_.ledger.RecordFailure(eval, attempt, "late"), JobUpdate::kStale);
  EXPECT_FALSE(store_.ledger.MarkRunning(eval, "w2", 0, attempt));
  EXPECT_EQ(Job("eval/B/baseline/run2").state, "succeeded");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "1");
  EXPECT_EQ(Query("SELECT aggregate_throughput_mbps FROM metrics"), "120.5");
  EXPECT_EQ(store_.reader.Progress(campaign_.id).succeeded, 2);
  EXPECT_EQ(store_.ledger.RetryFailed(campaign_.id), 0);  // nothing failed: succeeded jobs stay
  EXPECT_EQ(Job("eval/B/baseline/run2").state, "succeeded");
}

TEST_F(StoreTest, MetricsRowHoldsTheEvalResult) {
  store_.ledger.Submit(campaign_);
  store_.ledger.MarkRunning(Id("position/C/oracle"), "w1", 0, 1);
  store_.recorder.RecordSuccess(Id("position/C/oracle"), 1, PositionResult(50, 35, 10));
  Start("eval/C/oracle/run1");
  json result = EvalResult(1, 80.25, 0.0);
  result["mean_delay_ms"] = nullptr;  // nothing received: undefined, not zero
  result["position"] = {50.0, 35.0, 10.0};
  ASSERT_EQ(store_.recorder.RecordSuccess(Id("eval/C/oracle/run1"), 1, result),
            JobUpdate::kSucceeded);
  const auto rows = store_.reader.Metrics(campaign_.id);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].scenario, "C");
  EXPECT_EQ(rows[0].label, "oracle");
  EXPECT_EQ(rows[0].rng_run, 1);
  EXPECT_DOUBLE_EQ(rows[0].aggregate_throughput_mbps.value_or(-1), 80.25);
  EXPECT_FALSE(rows[0].mean_delay_ms.has_value());
  EXPECT_DOUBLE_EQ(*rows[0].loss_ratio, 0.01);
  EXPECT_DOUBLE_EQ(*rows[0].min_snr_db, 12.5);
  EXPECT_EQ(rows[0].n_los, 4);
  EXPECT_EQ(rows[0].n_ues, 4);
  EXPECT_EQ(rows[0].demands_met, 3);
  EXPECT_DOUBLE_EQ(rows[0].y, 35.0);
  EXPECT_EQ(Job("eval/C/oracle/run1").result->at("aggregate_throughput_mbps"), 80.25);
}

TEST_F(StoreTest, RetriesUntilExhaustedThenFailsWithDependents) {
  store_.ledger.Submit(campaign_);
  const std::string train = Id("train/C/seed1");
  ASSERT_EQ(Job("train/C/seed1").max_attempts, 2);  // mini: retries 1
  store_.ledger.MarkRunning(train, "w1", 0, 1);
  EXPECT_EQ(store_.ledger.RecordFailure(train, 1, "exit code 3: ns-3 aborted"),
            JobUpdate::kRetrying);
  JobRecord job = Job("train/C/seed1");
  EXPECT_EQ(job.state, "ready");
  EXPECT_EQ(job.attempt, 2);
  EXPECT_EQ(job.error, "exit code 3: ns-3 aborted");
  EXPECT_FALSE(job.worker_id.has_value());
  store_.ledger.MarkRunning(train, "w2", 0, 2);
  EXPECT_EQ(store_.ledger.RecordFailure(train, 2, "exit code 1: out of memory"),
            JobUpdate::kFailed);
  job = Job("train/C/seed1");
  EXPECT_EQ(job.state, "failed");
  EXPECT_EQ(job.attempt, 2);
  EXPECT_EQ(job.error, "exit code 1: out of memory");
  // Its 12 evals (rl + 5 offsets, 2 runs) can never run.
  EXPECT_EQ(Job("eval/C/offset2/run2").state, "failed");
  EXPECT_EQ(Job("eval/C/offset2/run2").error, "dependency " + train + " failed");
  EXPECT_EQ(store_.reader.Progress(campaign_.id).failed, 13);
  EXPECT_EQ(Job("eval/B/rl/run1").state, "pending");  // other scenario untouched
}

TEST_F(StoreTest, MalformedResultIsAFailedAttempt) {
  store_.ledger.Submit(campaign_);
  store_.ledger.MarkRunning(Id("position/B/centroid"), "w1", 0, 1);
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("position/B/centroid"), 1, {{"n_los", 2}}),
            JobUpdate::kRetrying);
  EXPECT_EQ(Job("position/B/centroid").error, "malformed result: result has no \"position\"");
  store_.ledger.MarkRunning(Id("position/B/centroid"), "w1", 0, 2);
  store_.recorder.RecordSuccess(Id("position/B/centroid"), 2, PositionResult(40, 40, 10));
  Start("eval/B/centroid/run1");
  // An eval result of the wrong run is a wiring bug, not data.
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("eval/B/centroid/run1"), 1, EvalResult(2, 10, 1)),
            JobUpdate::kRetrying);
  EXPECT_EQ(Job("eval/B/centroid/run1").error,
            "malformed result: result is of RngRun 2, the job's is 1");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "0");
}

TEST_F(StoreTest, LostWorkerJobsGoBack) {
  store_.ledger.Submit(campaign_);
  Start("train/B/seed1", "w1");
  Start("position/B/oracle", "w1");
  Start("position/C/oracle", "w2");
  const auto requeued = store_.ledger.RequeueWorker("w1");
  EXPECT_EQ(requeued, (std::vector<std::string>{Id("position/B/oracle"), Id("train/B/seed1")}));
  const JobRecord job = Job("train/B/seed1");
  EXPECT_EQ(job.state, "ready");
  EXPECT_EQ(job.attempt, 2);
  EXPECT_EQ(job.max_attempts, 3) << "a lost worker does not use the job's retries";
  EXPECT_EQ(Query("SELECT infra_losses FROM jobs WHERE id = '" + Id("train/B/seed1") + "'"), "1");
  EXPECT_EQ(job.error, "worker w1 was lost");
  EXPECT_EQ(Job("position/C/oracle").state, "running");
  // The lost worker's result, should it still arrive, is stale.
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("train/B/seed1"), 1, PositionResult(1, 1, 10)),
            JobUpdate::kStale);
  EXPECT_TRUE(store_.ledger.RequeueWorker("w1").empty());
  const auto running = store_.ledger.ListRunning();
  ASSERT_EQ(running.size(), 1u);
  EXPECT_EQ(running[0].worker_id, "w2");
  EXPECT_DOUBLE_EQ(running[0].started_at, 1000.0);
}

TEST_F(StoreTest, ProvenanceIsKeptAndMixedBuildsAreTold) {
  store_.ledger.Submit(campaign_);
  Provenance a{"host-a", "v1-3-gabc", "3.37", "1.13.0", "0.10.2", std::string(64, 'f')};
  int attempt = Start("position/B/baseline");
  ASSERT_EQ(store_.recorder.RecordSuccess(Id("position/B/baseline"), attempt,
                                          PositionResult(50, 50, 25), "w1", &a),
            JobUpdate::kSucceeded);
  EXPECT_EQ(Query("SELECT host || ' ' || rlpos_version || ' ' || ns3_version || ' ' || "
                  "torch_version || ' ' || cyclonedds_version || ' ' || scenario_sha256 FROM jobs "
                  "WHERE id = '" +
                  Id("position/B/baseline") + "'"),
            "host-a v1-3-gabc 3.37 1.13.0 0.10.2 " + std::string(64, 'f'));
  EXPECT_EQ(
      store_.reader.CampaignBuilds(campaign_.id),
      std::vector<std::string>{"rlpos v1-3-gabc, ns-3 3.37, libtorch 1.13.0, Cyclone DDS 0.10.2"});
  // Another job from another build: the campaign's results are mixed.
  Provenance b = a;
  b.rlpos_version = "v1-4-gdef";
  attempt = Start("position/C/baseline");
  store_.recorder.RecordSuccess(Id("position/C/baseline"), attempt, PositionResult(50, 50, 25),
                                "w1", &b);
  EXPECT_EQ(store_.reader.CampaignBuilds(campaign_.id).size(), 2u);
}

TEST_F(StoreTest, InfrastructureLossesHaveTheirOwnCap) {
  store_.ledger.Submit(campaign_);
  const std::string key = "position/B/oracle";
  // Ten losses: each a new attempt, none of the job's retries used.
  for (int loss = 1; loss <= 10; ++loss) {
    Start(key, "w" + std::to_string(loss));
    ASSERT_EQ(store_.ledger.RequeueWorker("w" + std::to_string(loss)).size(), 1u);
    EXPECT_EQ(Job(key).state, "ready") << loss;
    EXPECT_EQ(Job(key).max_attempts - Job(key).attempt, 1) << "retries left after loss " << loss;
  }
  // The eleventh fails it for good, and its evals with it.
  Start(key, "w11");
  store_.ledger.RequeueWorker("w11");
  EXPECT_EQ(Job(key).state, "failed");
  EXPECT_EQ(Job(key).error,
            "worker w11 was lost: 11 infrastructure losses, more than the cap of 10");
  EXPECT_EQ(Job("eval/B/oracle/run1").state, "failed");
  // Its own failures still count against retries (1 here): a retry of the campaign starts over.
  store_.ledger.RetryFailed(campaign_.id);
  EXPECT_EQ(Query("SELECT infra_losses FROM jobs WHERE id = '" + Id(key) + "'"), "0");
  const int attempt = Start(key);
  EXPECT_EQ(store_.ledger.RecordFailure(Id(key), attempt, "boom"), JobUpdate::kRetrying);
  EXPECT_EQ(store_.ledger.RecordFailure(Id(key), attempt + 1, "boom"), JobUpdate::kStale)
      << "not running";
}

TEST_F(StoreTest, CancelThenRetry) {
  store_.ledger.Submit(campaign_);
  store_.ledger.MarkRunning(Id("position/B/baseline"), "w1", 0, 1);
  store_.recorder.RecordSuccess(Id("position/B/baseline"), 1, PositionResult(50, 50, 25));
  Start("eval/B/baseline/run1", "w1");
  Start("train/B/seed1", "w2");

  const auto stopped = store_.ledger.CancelCampaign(campaign_.id);
  ASSERT_EQ(stopped.size(), 2u);
  EXPECT_EQ(stopped[0].id, Id("eval/B/baseline/run1"));
  EXPECT_EQ(stopped[0].worker_id, "w1");
  CampaignProgress p = store_.reader.Progress(campaign_.id);
  EXPECT_EQ(p.state, "cancelled");
  EXPECT_EQ(p.succeeded, 1);
  EXPECT_EQ(p.cancelled, 43);
  EXPECT_TRUE(store_.ledger.ListReady().empty());
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("train/B/seed1"), 1, PositionResult(1, 1, 10)),
            JobUpdate::kStale);

  EXPECT_EQ(store_.ledger.RetryFailed(campaign_.id), 43);
  p = store_.reader.Progress(campaign_.id);
  EXPECT_EQ(p.state, "active");
  EXPECT_EQ(p.succeeded, 1);
  // Producers and the baseline evals (their position is known) are ready; the rest wait.
  EXPECT_EQ(p.ready, 7 + 2);
  EXPECT_EQ(p.pending, 43 - 9);
  const JobRecord train = Job("train/B/seed1");
  EXPECT_EQ(train.attempt, 2);
  EXPECT_EQ(train.max_attempts, 3);  // a fresh budget: attempt 2 plus one retry
  EXPECT_EQ(testing::FormatPlacement(Job("eval/B/baseline/run1").placement), "50,50,25");
  EXPECT_THROW(store_.ledger.CancelCampaign("000000000000"), StoreError);
  EXPECT_THROW(store_.ledger.RetryFailed("000000000000"), StoreError);
}

TEST_F(StoreTest, RetryBringsFailedDependencyAndDependentsBack) {
  store_.ledger.Submit(campaign_);
  for (int attempt = 1; attempt <= 2; ++attempt) {
    store_.ledger.MarkRunning(Id("train/B/seed1"), "w1", 0, attempt);
    store_.ledger.RecordFailure(Id("train/B/seed1"), attempt, "boom");
  }
  ASSERT_EQ(Job("eval/B/rl/run1").state, "failed");
  EXPECT_EQ(store_.ledger.RetryFailed(campaign_.id), 13);
  EXPECT_EQ(Job("train/B/seed1").state, "ready");
  EXPECT_EQ(Job("train/B/seed1").attempt, 3);
  EXPECT_EQ(Job("eval/B/rl/run1").state, "pending");
  EXPECT_FALSE(Job("eval/B/rl/run1").error.has_value());
}

TEST_F(StoreTest, CampaignFinishesAndViewsAnswer) {
  store_.ledger.Submit(campaign_);
  int evals = 0;
  for (int round = 0; round < 3; ++round) {
    for (const auto& job : store_.ledger.ListReady()) {
      ASSERT_TRUE(store_.ledger.MarkRunning(job.id, "w1", 0, job.attempt));
      const JobRecord record = *store_.reader.GetJob(job.id);
      const json result = job.params.kind == JobKind::kEval
                              ? EvalResult(static_cast<std::uint64_t>(*record.params.rng_run),
                                           100.0 + static_cast<double>(*record.params.rng_run), 2.0)
                              : PositionResult(50, 35, 10);
      ASSERT_EQ(store_.recorder.RecordSuccess(job.id, job.attempt,
                                              AtJobPosition(store_.reader, job.id, result)),
                JobUpdate::kSucceeded);
      evals += job.params.kind == JobKind::kEval ? 1 : 0;
    }
  }
  EXPECT_EQ(evals, 36);
  const CampaignProgress p = store_.reader.Progress(campaign_.id);
  EXPECT_EQ(p.state, "finished");
  EXPECT_EQ(p.succeeded, 44);
  EXPECT_EQ(store_.reader.AllProgress().size(), 1u);
  EXPECT_EQ(store_.reader.Metrics(campaign_.id).size(), 36u);

  // Queries like docs/results-database.md's examples, as a user would type them.
  EXPECT_EQ(Query("SELECT COUNT(*) FROM v_eval_runs WHERE scenario = 'B' AND positioner = 'rl'"),
            "2");
  EXPECT_EQ(Query("SELECT ROUND(AVG(throughput_mbps), 2) FROM v_eval_runs "
                  "WHERE scenario = 'C' AND positioner = 'offset1'"),
            "101.5");
  EXPECT_EQ(Query("SELECT succeeded || '/' || total FROM v_campaign_progress "
                  "WHERE name = 'mini'"),
            "44/44");
  EXPECT_EQ(Query("SELECT throughput_mbps FROM v_eval_runs WHERE scenario = 'B' "
                  "AND positioner = 'baseline' AND rng_run = 2"),
            "102.0");
}

TEST_F(StoreTest, ListReadyOldestCampaignFirst) {
  store_.ledger.Submit(campaign_);
  CampaignSpec other = testing::MiniSpec();
  other.name = "later";
  now_ += 10;
  ExpandedCampaign later = ExpandCampaign(other);
  later.use_cache = false;  // else its jobs would wait for their twins in the first one
  const SubmitResult second = store_.ledger.Submit(later);
  ASSERT_TRUE(second.created);
  const auto ready = store_.ledger.ListReady();
  ASSERT_EQ(ready.size(), 16u);
  EXPECT_EQ(ready[0].campaign_id, campaign_.id);
  EXPECT_EQ(ready[8].campaign_id, second.campaign_id);
  // A cancelled campaign's jobs are not offered.
  store_.ledger.CancelCampaign(campaign_.id);
  EXPECT_EQ(store_.ledger.ListReady().size(), 8u);
}

// A train job's files come with its result: written beside the database, listed with their
// sha256 and size, and served with the result to a job of the same content.
TEST_F(StoreTest, ArtifactsAreStoredBesideTheDatabase) {
  store_.ledger.Submit(campaign_);
  const int attempt = Start("train/B/seed1");
  const std::vector<ArtifactFile> files{
      {"policy.pt", Sha256Hex("weights"), "weights"},
      {"learning_curve.csv", Sha256Hex("e,r\n1,2\n"), "e,r\n1,2\n"}};
  ASSERT_EQ(store_.recorder.RecordSuccess(Id("train/B/seed1"), attempt, PositionResult(50, 50, 30),
                                          "w1", nullptr, files),
            JobUpdate::kSucceeded);
  const auto rows = store_.reader.Artifacts(campaign_.id);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].name, "learning_curve.csv");
  EXPECT_EQ(rows[1].name, "policy.pt");
  EXPECT_EQ(rows[1].path, Id("train/B/seed1") + "/policy.pt");
  EXPECT_EQ(rows[1].sha256, Sha256Hex("weights"));
  EXPECT_EQ(rows[1].bytes, 7);
  EXPECT_EQ(ArtifactsDirOf(dir_.File("rlpos.db")), dir_.File("rlpos.artifacts"));
  std::ifstream policy(dir_.File("rlpos.artifacts") + "/" + rows[1].path);
  std::string text((std::istreambuf_iterator<char>(policy)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "weights");
  EXPECT_EQ(store_.reader.Artifacts(Id("train/B/seed1")).size(), 2u);  // by job id too
  EXPECT_TRUE(store_.reader.Artifacts(Id("position/B/oracle")).empty());
}

TEST_F(StoreTest, ArtifactsThatCannotBeWrittenFailTheAttempt) {
  store_.ledger.Submit(campaign_);
  // A file where the artifacts folder should be.
  std::ofstream(dir_.File("rlpos.artifacts")) << "in the way";
  const int attempt = Start("train/B/seed1");
  EXPECT_EQ(store_.recorder.RecordSuccess(Id("train/B/seed1"), attempt, PositionResult(50, 50, 30),
                                          "w1", nullptr, {{"policy.pt", Sha256Hex("w"), "w"}}),
            JobUpdate::kRetrying);
  EXPECT_NE(Job("train/B/seed1").error.value_or("").find("cannot store its artifacts"),
            std::string::npos);
  EXPECT_TRUE(store_.reader.Artifacts(campaign_.id).empty());
}

TEST(ArtifactFiles, PathsStayInsideTheFolder) {
  EXPECT_EQ(ArtifactRelativePath("c0ffee/train/B/seed1", "policy.pt"),
            "c0ffee/train/B/seed1/policy.pt");
  EXPECT_THROW(ArtifactRelativePath("c0ffee/../etc", "policy.pt"), std::invalid_argument);
  EXPECT_THROW(ArtifactRelativePath("/abs/job", "policy.pt"), std::invalid_argument);
  EXPECT_THROW(ArtifactRelativePath("c0ffee/train", "../x"), std::invalid_argument);
  EXPECT_THROW(ArtifactRelativePath("c0ffee/train", "a/b"), std::invalid_argument);
  EXPECT_EQ(ArtifactsDirOf("results/rlpos.db"), "results/rlpos.artifacts");
  EXPECT_EQ(ArtifactsDirOf("results/db"), "results/db.artifacts");
}

TEST(ArtifactChecks, NamesSizesAndHashes) {
  EXPECT_EQ(CheckArtifacts({{"policy.pt", Sha256Hex("x"), "x"}}), "");
  EXPECT_EQ(CheckArtifacts({{"../policy.pt", Sha256Hex("x"), "x"}}), "unknown artifact name");
  EXPECT_EQ(CheckArtifacts({{"policy.pt", Sha256Hex("y"), "x"}}),
            "artifact policy.pt does not match its sha256");
  EXPECT_EQ(
      CheckArtifacts({{"policy.pt", Sha256Hex("x"), "x"}, {"policy.pt", Sha256Hex("x"), "x"}}),
      "artifact policy.pt twice");
  const std::string big(wire::kMaxArtifactBytes + 1, 'a');
  EXPECT_EQ(CheckArtifacts({{"policy.pt", Sha256Hex(big), big}}), "artifact policy.pt too large");
  const std::string half(wire::kMaxArtifactBytes, 'a');
  EXPECT_EQ(CheckArtifacts({{"policy.pt", Sha256Hex(half), half},
                            {"trajectory.csv", Sha256Hex(half), half},
                            {"result.json", Sha256Hex("x"), "x"}}),
            "artifacts too large together");
}

}  // namespace
}  // namespace rlpos
