// The result cache: a job takes the result of a succeeded job of the same content instead of
// running; identical jobs that would run at once run once; --no-cache runs everything.
#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "common/campaign/job_content.h"
#include "common/hash/sha256.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using testing::AtJobPosition;
using testing::EvalResult;
using testing::PositionResult;

class ResultCacheTest : public ::testing::Test {
 protected:
  ResultCacheTest() : store_(dir_.File("rlpos.db")) {}

  // Where a train or position job's stand-in result puts the UAV: a place of its own for each
  // positioner (an offset is 10 m from the trained position).
  static Vec3 Produced(const ReadyJob& job) {
    if (job.params.positioner == "baseline")
      return {12, 12, 30};
    if (job.params.positioner == "centroid")
      return {24, 12, 30};
    if (job.params.positioner == "oracle")
      return {36, 12, 30};
    return {50, 50, 30};
  }
  // Plays the workers: runs every ready job until none is left; trains and positions end where
  // `produced` says, evals give a throughput of 100 + run. Returns how many jobs ran.
  int RunAll(const std::function<Vec3(const ReadyJob&)>& produced = Produced) {
    int ran = 0;
    for (auto ready = store_.ledger.ListReady(); !ready.empty();
         ready = store_.ledger.ListReady()) {
      for (const auto& job : ready) {
        EXPECT_TRUE(store_.ledger.MarkRunning(job.id, "w1", 0, job.attempt));
        nlohmann::json result =
            job.params.kind == JobKind::kEval
                ? AtJobPosition(store_.reader, job.id,
                                EvalResult(*job.params.rng_run, 100.0 + *job.params.rng_run, 5))
                : PositionResult(produced(job).x, produced(job).y, produced(job).z);
        EXPECT_EQ(store_.recorder.RecordSuccess(job.id, job.attempt, result, "w1"),
                  JobUpdate::kSucceeded)
            << job.id;
        ++ran;
      }
    }
    return ran;
  }
  std::string Query(const std::string& sql) {
    return testing::QueryOne(dir_.File("rlpos.db"), sql);
  }
  static ExpandedCampaign Named(const std::string& name, bool use_cache = true) {
    CampaignSpec spec = testing::MiniSpec();
    spec.name = name;
    ExpandedCampaign campaign = ExpandCampaign(spec);
    campaign.use_cache = use_cache;
    return campaign;
  }
  // The mini campaign with two train seeds and rl alone, submitted.
  ExpandedCampaign SubmitTwoSeedsOfRl() {
    CampaignSpec spec = testing::MiniSpec();
    spec.train.seeds = {1, 2};
    spec.positioners = {"rl"};
    const ExpandedCampaign campaign = ExpandCampaign(spec);
    store_.ledger.Submit(campaign);
    return campaign;
  }

  testing::TempDir dir_;
  CoordinatorStore store_;
};

TEST_F(ResultCacheTest, ACampaignUnderANewNameIsServedWholeAtSubmit) {
  const ExpandedCampaign first = Named("first");
  store_.ledger.Submit(first);
  const int ran = RunAll();
  EXPECT_EQ(ran, static_cast<int>(first.jobs.size()));

  const ExpandedCampaign again = Named("again");
  ASSERT_NE(again.id, first.id);
  store_.ledger.Submit(again);
  EXPECT_TRUE(store_.ledger.ListReady().empty());
  const CampaignProgress progress = store_.reader.Progress(again.id);
  EXPECT_EQ(progress.succeeded, progress.total);
  EXPECT_EQ(progress.cached, progress.total);
  EXPECT_EQ(store_.reader.Progress(first.id).cached, 0);
  EXPECT_EQ(progress.state, "finished");
  // Every row says where its result came from, and the metrics are the same.
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs WHERE campaign_id = '" + again.id +
                  "' AND cached_from IS NULL"),
            "0");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs a JOIN jobs f ON f.id = a.cached_from WHERE "
                  "a.campaign_id = '" +
                  again.id + "' AND f.campaign_id = '" + first.id + "'"),
            std::to_string(first.jobs.size()));
  const auto metrics_first = store_.reader.Metrics(first.id),
             metrics_again = store_.reader.Metrics(again.id);
  ASSERT_EQ(metrics_again.size(), metrics_first.size());
  for (std::size_t i = 0; i < metrics_first.size(); ++i) {
    EXPECT_EQ(metrics_again[i].label, metrics_first[i].label);
    EXPECT_EQ(metrics_again[i].rng_run, metrics_first[i].rng_run);
    EXPECT_EQ(metrics_again[i].aggregate_throughput_mbps,
              metrics_first[i].aggregate_throughput_mbps);
  }
}

TEST_F(ResultCacheTest, RetryTakesWhatAnotherCampaignComputedMeanwhile) {
  const ExpandedCampaign stopped = Named("stopped");
  store_.ledger.Submit(stopped);
  store_.ledger.CancelCampaign(stopped.id);
  const ExpandedCampaign done = Named("done");
  store_.ledger.Submit(done);
  EXPECT_EQ(RunAll(), static_cast<int>(done.jobs.size()));

  EXPECT_EQ(store_.ledger.RetryFailed(stopped.id), static_cast<int>(stopped.jobs.size()));
  EXPECT_TRUE(store_.ledger.ListReady().empty());  // nothing left to run
  const CampaignProgress progress = store_.reader.Progress(stopped.id);
  EXPECT_EQ(progress.cached, progress.total);
  EXPECT_EQ(progress.state, "finished");
}

TEST_F(ResultCacheTest, NoCacheRunsEveryJob) {
  const ExpandedCampaign first = Named("first");
  store_.ledger.Submit(first);
  RunAll();
  const ExpandedCampaign again = Named("again", false);
  store_.ledger.Submit(again);
  EXPECT_EQ(RunAll(), static_cast<int>(again.jobs.size()));
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs WHERE cached_from IS NOT NULL"), "0");
}

TEST_F(ResultCacheTest, IdenticalEvalsInACampaignRunOnce) {
  // Two train seeds that end at the same position: their rl evals of one run are one content
  // (the train seed only says where a position came from).
  SubmitTwoSeedsOfRl();
  const int ran = RunAll();
  // 2 scenarios x (2 trains + 2 runs of rl); rl@seed2's evals took rl's results.
  EXPECT_EQ(ran, 2 * (2 + 2));
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs WHERE label = 'rl@seed2' AND cached_from IS NOT "
                  "NULL AND state = 'succeeded'"),
            "4");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "8");
}

TEST_F(ResultCacheTest, AnotherPositionOrRunIsAnotherContent) {
  const ExpandedCampaign campaign = SubmitTwoSeedsOfRl();
  // Seed 2's training ends elsewhere: nothing is shared.
  const int ran = RunAll([](const ReadyJob& job) {
    return Vec3{job.params.train_seed == 2u ? 55.0 : 50.0, 50, 30};
  });
  EXPECT_EQ(ran, static_cast<int>(campaign.jobs.size()));
  EXPECT_EQ(Query("SELECT COUNT(*) FROM jobs WHERE cached_from IS NOT NULL"), "0");
}

TEST_F(ResultCacheTest, AJobWaitingForATwinThatFailsRunsItself) {
  const ExpandedCampaign first = Named("first");
  const ExpandedCampaign again = Named("again");
  store_.ledger.Submit(first);
  store_.ledger.Submit(again);
  // Every ready job of "again" waits for its twin in "first".
  for (const auto& job : store_.ledger.ListReady())
    EXPECT_EQ(job.campaign_id, first.id) << job.id;
  const std::string train = first.id + "/train/B/seed1";
  const std::string twin = again.id + "/train/B/seed1";
  const int attempt = store_.reader.GetJob(train)->attempt;
  ASSERT_TRUE(store_.ledger.MarkRunning(train, "w1", 0, attempt));
  store_.ledger.CancelCampaign(first.id);
  bool listed = false;
  for (const auto& job : store_.ledger.ListReady())
    listed = listed || job.id == twin;
  EXPECT_TRUE(listed);
}

TEST_F(ResultCacheTest, AWaitingJobIsServedWhenItsTwinSucceeds) {
  const ExpandedCampaign first = Named("first");
  const ExpandedCampaign again = Named("again");
  store_.ledger.Submit(first);
  store_.ledger.Submit(again);
  const std::string train = first.id + "/train/B/seed1";
  ASSERT_TRUE(store_.ledger.MarkRunning(train, "w1", 0, 1));
  ASSERT_EQ(store_.recorder.RecordSuccess(train, 1, PositionResult(50, 50, 30), "w1", nullptr,
                                          {{"policy.pt", Sha256Hex("weights"), "weights"}}),
            JobUpdate::kSucceeded);
  const auto served = store_.reader.GetJob(again.id + "/train/B/seed1");
  ASSERT_TRUE(served);
  EXPECT_EQ(served->state, "succeeded");
  EXPECT_EQ(Query("SELECT cached_from FROM jobs WHERE id = '" + again.id + "/train/B/seed1'"),
            train);
  // Its artifacts are the source's files.
  const auto artifacts = store_.reader.Artifacts(again.id);
  ASSERT_EQ(artifacts.size(), 1u);
  EXPECT_EQ(artifacts[0].path, train + "/policy.pt");
  EXPECT_EQ(artifacts[0].cached_from, train);
}

TEST(JobContent, EveryFieldThatChangesARunChangesTheKey) {
  JobParams train;
  train.kind = JobKind::kTrain;
  train.scenario = "B";
  train.train_seed = 1;
  train.fidelity = "analytic";
  const std::string base = JobContentBase(train, "aa", "v1");
  EXPECT_EQ(JobContentBase(train, "aa", "v1"), base);
  EXPECT_NE(JobContentBase(train, "ab", "v1"), base);  // scenario document
  EXPECT_NE(JobContentBase(train, "aa", "v2"), base);  // build
  std::map<std::string, JobParams> changed;
  changed["seed"] = train, changed["seed"].train_seed = 2;
  changed["fidelity"] = train, changed["fidelity"].fidelity = "packet";
  changed["episodes"] = train, changed["episodes"].train_episodes = 10;
  changed["duration"] = train, changed["duration"].duration_s = 5;
  changed["warmup"] = train, changed["warmup"].warmup_s = 1;
  changed["overrides"] = train, changed["overrides"].overrides = {{"uav.step", "5"}};
  changed["kind"] = train, changed["kind"].kind = JobKind::kPosition;
  for (const auto& [what, params] : changed)
    EXPECT_NE(JobContentBase(params, "aa", "v1"), base) << what;
  // A named policy's position job: the policy is its content, so another policy's placement is
  // never served.
  JobParams rl_position;
  rl_position.kind = JobKind::kPosition;
  rl_position.scenario = "B";
  rl_position.positioner = "rl";
  rl_position.policy_sha256 = std::string(64, 'a');
  JobParams other_policy = rl_position;
  other_policy.policy_sha256 = std::string(64, 'b');
  EXPECT_NE(JobContentBase(other_policy, "aa", "v1"), JobContentBase(rl_position, "aa", "v1"));
  // The scenario's name in its campaign is not content.
  JobParams renamed = train;
  renamed.scenario = "other";
  EXPECT_EQ(JobContentBase(renamed, "aa", "v1"), base);
}

// Keys of results already cached: the same content keeps its key across releases of the code
// that computes it, so a store's cached results keep serving.
TEST(JobContent, TheKeyOfTheSameContentStaysTheSame) {
  JobParams train;
  train.kind = JobKind::kTrain;
  train.scenario = "B";
  train.train_seed = 3;
  train.fidelity = "packet";
  train.train_episodes = 40;
  train.duration_s = 2;
  train.warmup_s = 0.5;
  train.overrides = {{"wifi.mode", "adhoc"}, {"agent.algorithm", "ppo"}};
  JobParams position;
  position.kind = JobKind::kPosition;
  position.scenario = "C";
  position.positioner = "oracle";
  position.duration_s = 10;
  JobParams eval;
  eval.kind = JobKind::kEval;
  eval.scenario = "B";
  eval.train_seed = 2;
  eval.rng_run = 17;
  eval.warmup_s = 1;
  EXPECT_EQ(JobContentBase(train, "aa", "v1"),
            "deb8bbf5e9fecb028c06b6c954bc606efe0f8cc8593813b78bf80d3c16cecf11");
  EXPECT_EQ(JobContentBase(position, "aa", "v1"),
            "798cf272acf547f9dee94478b030289358c6cb136f2361f94a12ad285cdfbbe8");
  EXPECT_EQ(JobContentBase(eval, "aa", "v1"),
            "3fa01a8d8a027dd9898ef77e519300c37736be81e89eea66d737235c0da6815c");
}

TEST(JobContent, AnEvalsKeyNeedsItsPositionButNotItsTrainSeed) {
  JobParams eval;
  eval.kind = JobKind::kEval;
  eval.rng_run = 3;
  eval.train_seed = 1;
  const std::string base = JobContentBase(eval, "aa", "v1");
  JobParams other_seed = eval;
  other_seed.train_seed = 2;
  EXPECT_EQ(JobContentBase(other_seed, "aa", "v1"), base);
  JobParams other_run = eval;
  other_run.rng_run = 4;
  EXPECT_NE(JobContentBase(other_run, "aa", "v1"), base);
  EXPECT_FALSE(JobContentKey(base, JobKind::kEval, std::nullopt));
  const auto key = JobContentKey(base, JobKind::kEval, Placement{{10, 20, 30}});
  ASSERT_TRUE(key);
  // One UAV's key is what it was before placements: single-UAV results cached then still serve.
  EXPECT_EQ(*key, Sha256Hex(base + "|10000000,20000000,30000000"));
  EXPECT_EQ(JobContentKey(base, JobKind::kEval, Placement{{10 + 1e-9, 20, 30}}), key);
  EXPECT_NE(JobContentKey(base, JobKind::kEval, Placement{{10.001, 20, 30}}), key);
  EXPECT_EQ(JobContentKey(base, JobKind::kTrain, std::nullopt), base);
}

TEST(JobContent, APlacementsKeyHasEveryUavInOrder) {
  JobParams eval;
  eval.kind = JobKind::kEval;
  eval.rng_run = 3;
  const std::string base = JobContentBase(eval, "aa", "v1");
  const auto two = JobContentKey(base, JobKind::kEval, Placement{{10, 20, 30}, {40, 50, 30}});
  ASSERT_TRUE(two);
  EXPECT_NE(two, JobContentKey(base, JobKind::kEval, Placement{{10, 20, 30}}));
  EXPECT_NE(two, JobContentKey(base, JobKind::kEval, Placement{{40, 50, 30}, {10, 20, 30}}));
  EXPECT_NE(two, JobContentKey(base, JobKind::kEval, Placement{{10, 20, 30}, {40, 50, 31}}));
  EXPECT_EQ(two, JobContentKey(base, JobKind::kEval, Placement{{10, 20, 30}, {40, 50, 30 + 1e-9}}));
  EXPECT_FALSE(JobContentKey(base, JobKind::kEval, Placement{}));
}

}  // namespace
}  // namespace rlpos
