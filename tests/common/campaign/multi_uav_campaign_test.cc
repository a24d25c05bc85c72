// Campaigns of several UAVs: expansion (no offsets), placements bound and checked by the store,
// each UAV's metrics in uav_metrics / v_eval_uavs, and a schema-9 file's evals carried over.
#include <gtest/gtest.h>

#include <set>

#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;

ExpandedCampaign SeveralUavsCampaign() {
  ExpandedCampaign campaign =
      ExpandCampaign(ReadCampaignFile(testing::SourcePath("campaigns/several_uavs.json")));
  campaign.use_cache = false;  // the stand-in results below would serve each other
  return campaign;
}

// What `rlpos-sim eval --json` prints for two UAVs: the first serves 3 UEs, the second 1, which
// received nothing.
json EvalOfTwo(const Placement& at, std::uint64_t run) {
  const auto xyz = [](const Vec3& p) { return json::array({p.x, p.y, p.z}); };
  return {{"position", xyz(at[0])},
          {"run", run},
          {"aggregate_throughput_mbps", 150.0},
          {"mean_delay_ms", 20.0},
          {"loss_ratio", 0.1},
          {"n_los", 3},
          {"n_ues", 4},
          {"demands_met", 3},
          {"min_snr_db", 5.0},
          {"worst_ue_throughput_mbps", 0.0},
          {"jain_fairness", 0.75},
          {"uavs",
           {{{"name", "north"},
             {"position", xyz(at[0])},
             {"ues_served", 3},
             {"throughput_mbps", 150.0},
             {"mean_delay_ms", 20.0},
             {"loss_ratio", 0.0},
             {"n_los", 3},
             {"worst_ue_throughput_mbps", 50.0},
             {"jain_fairness", 1.0}},
            {{"name", "south"},
             {"position", xyz(at[1])},
             {"ues_served", 1},
             {"throughput_mbps", 0.0},
             {"mean_delay_ms", nullptr},
             {"loss_ratio", 1.0},
             {"n_los", 0},
             {"worst_ue_throughput_mbps", 0.0},
             {"jain_fairness", nullptr}}}}};
}

class MultiUavStoreTest : public ::testing::Test {
 protected:
  MultiUavStoreTest() : campaign_(SeveralUavsCampaign()), store_(dir_.File("rlpos.db")) {
    store_.ledger.Submit(campaign_);
  }
  std::string Id(const std::string& key) const { return campaign_.id + "/" + key; }
  JobRecord Job(const std::string& key) { return store_.reader.GetJob(Id(key)).value(); }
  JobUpdate Run(const std::string& key, const json& result) {
    const int attempt = Job(key).attempt;
    EXPECT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, attempt)) << key;
    return store_.recorder.RecordSuccess(Id(key), attempt, result);
  }
  std::string Query(const std::string& sql) {
    return testing::QueryOne(dir_.File("rlpos.db"), sql);
  }

  testing::TempDir dir_;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

TEST(MultiUavExpansion, EveryPositionerButTheOffsets) {
  const ExpandedCampaign campaign = SeveralUavsCampaign();
  EXPECT_EQ(campaign.jobs.size(), campaign.JobCount());
  std::set<std::string> labels;
  for (const auto& job : campaign.jobs)
    labels.insert(job.label);
  EXPECT_EQ(labels, (std::set<std::string>{"baseline", "centroid", "oracle", "rl", "rl@seed2",
                                           "rl@seed3"}));
  // 2 scenarios x (3 position + 3 train jobs + 6 labels x 10 runs).
  EXPECT_EQ(campaign.jobs.size(), 2u * (3 + 3 + 6 * 10));

  // Asked for offsets, a scenario of several UAVs gets none; a single-UAV one beside it does.
  json spec = {{"name", "mixed"},
               {"scenarios", {"scenarios/campus2.json", "scenarios/b.json"}},
               {"rng_runs", {1, 2}},
               {"positioners", {"offsets", "rl"}},
               {"train", {{"seeds", {1}}}}};
  const ExpandedCampaign mixed =
      ExpandCampaign(ParseCampaign(spec, testing::SourcePath("campaigns")));
  EXPECT_EQ(mixed.jobs.size(), mixed.JobCount());
  int campus_offsets = 0, b_offsets = 0;
  for (const auto& job : mixed.jobs) {
    if (job.label.rfind("offset", 0) == 0)
      ++(job.params.scenario == "campus2" ? campus_offsets : b_offsets);
  }
  EXPECT_EQ(campus_offsets, 0);
  EXPECT_EQ(b_offsets, 5 * 2);
}

TEST_F(MultiUavStoreTest, ATrainedPlacementIsBoundToEveryRlEval) {
  const json trained = {{"position", {20.0, 80.0, 25.0}},
                        {"positions", {{20.0, 80.0, 25.0}, {60.5, 15.0, 30.0}}}};
  ASSERT_EQ(Run("train/campus2/seed1", trained), JobUpdate::kSucceeded);
  const JobRecord eval = Job("eval/campus2/rl/run3");
  EXPECT_EQ(eval.state, "ready");
  EXPECT_EQ(testing::FormatPlacement(eval.placement), "20,80,25 60.5,15,30");
  // x, y, z hold the first UAV's position; positions_json all of them.
  EXPECT_EQ(
      Query("SELECT x || ',' || y || ',' || z || ' ' || positions_json FROM jobs WHERE id = '" +
            Id("eval/campus2/rl/run3") + "'"),
      "20.0,80.0,25.0 [[20.0,80.0,25.0],[60.5,15.0,30.0]]");
  // What a worker is ordered.
  int rl_evals = 0;
  for (const ReadyJob& job : store_.ledger.ListReady()) {
    if (job.params.kind != JobKind::kEval)
      continue;
    ++rl_evals;
    EXPECT_EQ(testing::FormatPlacement(job.placement), "20,80,25 60.5,15,30") << job.key;
  }
  EXPECT_EQ(rl_evals, 10);
}

TEST_F(MultiUavStoreTest, EachUavsMetricsLandInTheirTableAndView) {
  const Placement placement{{20, 80, 25}, {60.5, 15, 30}};
  ASSERT_EQ(Run("position/campus2/centroid",
                {{"position", {20, 80, 25}}, {"positions", {{20, 80, 25}, {60.5, 15, 30}}}}),
            JobUpdate::kSucceeded);
  ASSERT_EQ(Run("eval/campus2/centroid/run2", EvalOfTwo(placement, 2)), JobUpdate::kSucceeded);

  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "1");
  EXPECT_EQ(Query("SELECT group_concat(uav || ':' || uav_name || ':' || ues_served || ':' || "
                  "throughput_mbps || ':' || COALESCE(delay_ms, 'null') || ':' || "
                  "COALESCE(jain_fairness, 'null') || ':' || x, ' ') "
                  "FROM (SELECT * FROM v_eval_uavs ORDER BY uav)"),
            "0:north:3:150.0:20.0:1.0:20.0 1:south:1:0.0:null:null:60.5");
  EXPECT_EQ(
      Query("SELECT DISTINCT positioner || ' ' || rng_run || ' ' || campaign FROM v_eval_uavs"),
      "centroid 2 several-uavs");

  const std::vector<UavMetricRow> rows = store_.reader.UavMetrics(campaign_.id);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].name, "south");
  EXPECT_EQ(rows[1].uav, 1);
  EXPECT_EQ(rows[1].label, "centroid");
  EXPECT_EQ(rows[1].rng_run, 2);
  EXPECT_FALSE(rows[1].mean_delay_ms.has_value());
  EXPECT_DOUBLE_EQ(rows[1].loss_ratio.value(), 1.0);
  EXPECT_DOUBLE_EQ(rows[0].worst_ue_throughput_mbps.value(), 50.0);
}

TEST_F(MultiUavStoreTest, AResultOfAnotherPlacementOrThatDoesNotAddUpIsAFailedAttempt) {
  const Placement placement{{20, 80, 25}, {60.5, 15, 30}};
  ASSERT_EQ(Run("position/campus2/oracle",
                {{"position", {20, 80, 25}}, {"positions", {{20, 80, 25}, {60.5, 15, 30}}}}),
            JobUpdate::kSucceeded);
  // The second UAV elsewhere: another placement, although the first UAV's position matches.
  EXPECT_EQ(Run("eval/campus2/oracle/run1", EvalOfTwo({{20, 80, 25}, {60.5, 16, 30}}, 1)),
            JobUpdate::kRetrying);
  EXPECT_EQ(Job("eval/campus2/oracle/run1").error,
            "malformed result: result is of another placement than the job's");
  // Per-UAV shares that do not add up to the run's totals.
  json uneven = EvalOfTwo(placement, 1);
  uneven["uavs"][1]["ues_served"] = 2;
  EXPECT_EQ(Run("eval/campus2/oracle/run1", uneven), JobUpdate::kFailed);
  EXPECT_EQ(Job("eval/campus2/oracle/run1").error,
            "malformed result: result \"uavs\" do not add up to the run's totals");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM uav_metrics"), "0");
  EXPECT_EQ(Query("SELECT COUNT(*) FROM metrics"), "0");
}

TEST(MultiUavStore, ASingleUavEvalHasOneRowNamedUav) {
  testing::TempDir dir;
  ExpandedCampaign mini = testing::MiniCampaign();
  CoordinatorStore store(dir.File("rlpos.db"));
  store.ledger.Submit(mini);
  const std::string producer = mini.id + "/position/B/baseline";
  ASSERT_TRUE(store.ledger.MarkRunning(producer, "w1", 0, 1));
  ASSERT_EQ(store.recorder.RecordSuccess(producer, 1, testing::PositionResult(50, 35, 10)),
            JobUpdate::kSucceeded);
  const std::string eval = mini.id + "/eval/B/baseline/run1";
  ASSERT_TRUE(store.ledger.MarkRunning(eval, "w1", 0, 1));
  ASSERT_EQ(
      store.recorder.RecordSuccess(
          eval, 1, testing::AtJobPosition(store.reader, eval, testing::EvalResult(1, 120, 30))),
      JobUpdate::kSucceeded);
  const auto rows = store.reader.UavMetrics(mini.id);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].name, "uav");
  EXPECT_EQ(rows[0].uav, 0);
  EXPECT_DOUBLE_EQ(rows[0].throughput_mbps.value(), 120);
  EXPECT_EQ(rows[0].ues_served, 4);
  EXPECT_EQ(testing::QueryOne(dir.File("rlpos.db"),
                              "SELECT positions_json FROM jobs WHERE id = '" + eval + "'"),
            "<null>");
}

TEST(MultiUavStore, ASchemaNineFilesEvalsGetTheirOneUav) {
  testing::TempDir dir;
  const std::string file = dir.File("v9.db");
  {
    Database db(file, false, 1000);
    for (const Migration& m : Migrations()) {
      if (m.version > 9)
        break;
      db.Exec(m.sql);
      if (m.sql_after)
        db.Exec(m.sql_after);
    }
    db.Exec(
        "CREATE TABLE schema_version (version INTEGER NOT NULL);"
        "INSERT INTO schema_version VALUES (9);"
        "INSERT INTO campaigns (id, name, spec_json, created_at, state, max_attempts, "
        "job_timeout_s) VALUES ('c0ffee', 'old', '{}', 1000, 'finished', 1, 60);"
        "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, rng_run, state, "
        "attempt, max_attempts, timeout_s, created_at, position_rule_json, x, y, z) VALUES "
        "('c0ffee/e', 'c0ffee', 0, 'eval', 'e', 'B', 'rl', 4, 'succeeded', 1, 1, 60, 1000, "
        "'{\"offset\":0}', 1, 2, 3);"
        "INSERT INTO metrics (job_id, campaign_id, scenario, label, rng_run, "
        "aggregate_throughput_mbps, mean_delay_ms, loss_ratio, n_los, n_ues, demands_met, "
        "min_snr_db, x, y, z, worst_ue_throughput_mbps, jain_fairness) VALUES "
        "('c0ffee/e', 'c0ffee', 'B', 'rl', 4, 99.5, 12, 0, 2, 4, 4, 20, 1, 2, 3, 10, 0.9);");
  }
  CoordinatorStore store(file);
  EXPECT_EQ(store.db.SchemaVersion(), LatestSchemaVersion());
  const auto rows = store.reader.UavMetrics("c0ffee");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].name, "uav");
  EXPECT_EQ(rows[0].ues_served, 4);
  EXPECT_EQ(rows[0].n_los, 2);
  EXPECT_DOUBLE_EQ(rows[0].throughput_mbps.value(), 99.5);
  EXPECT_DOUBLE_EQ(rows[0].jain_fairness.value(), 0.9);
  EXPECT_DOUBLE_EQ(rows[0].z, 3);
  EXPECT_EQ(testing::FormatPlacement(store.reader.GetJob("c0ffee/e")->placement), "1,2,3");
}

}  // namespace
}  // namespace rlpos
