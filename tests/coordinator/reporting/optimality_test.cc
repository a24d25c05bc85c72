// The optimality section: each placement's reward over the oracle's
// (common/store/optimality_rows.h) and its statistics per algorithm (named policy, positioner) and
// UAV count (coordinator/reporting/optimality.h), from hand-made rows and from a results store,
// and in the report folder.
#include "coordinator/reporting/optimality.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/store/optimality_rows.h"
#include "common/store/sqlite_db.h"
#include "coordinator/reporting/report_markdown.h"
#include "coordinator/reporting/report_writer.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

OptimalityRow Row(const std::string& scenario, int uavs, const std::string& algorithm,
                  std::uint64_t seed, double rl, double oracle) {
  OptimalityRow row;
  row.scenario = scenario;
  row.uavs = uavs;
  row.algorithm = algorithm;
  row.train_seed = seed;
  row.label = "rl@" + algorithm + (seed > 1 ? "@seed" + std::to_string(seed) : "");
  row.trained = true;
  row.runs = 1;
  row.rl_reward = rl;
  row.oracle_reward = oracle;
  return row;
}

// dqn, 1 UAV: ratios 1.0, 0.99, 0.9, 0.5, 0.97 (sorted 0.5 0.9 0.97 0.99 1.0);
// ppo, 2 UAVs: 1.02 (rl beats the coordinate descent) and 0.94; ppo, 1 UAV: 0.95 exactly;
// sac, 1 UAV: an oracle reward of 0, which gives no ratio; an unrecorded algorithm: 0.8.
std::vector<OptimalityRow> OptimalityRows() {
  return {Row("S2", 2, "ppo", 1, 1.02, 1.0), Row("A", 1, "dqn", 1, 0.5, 0.5),
          Row("B", 1, "dqn", 1, 0.495, 0.5), Row("C", 1, "dqn", 1, 0.45, 0.5),
          Row("C", 1, "", 1, 0.4, 0.5),      Row("D", 1, "dqn", 1, 0.25, 0.5),
          Row("E", 1, "dqn", 1, 0.485, 0.5), Row("S3", 2, "ppo", 1, 0.94, 1.0),
          Row("A", 1, "ppo", 2, 0.475, 0.5), Row("A", 1, "sac", 1, 0.0, 0.0)};
}

TEST(Optimality, TheRatioIsRlsRewardOverTheOracles) {
  EXPECT_DOUBLE_EQ(*Row("A", 1, "dqn", 1, 0.45, 0.5).Ratio(), 0.9);
  EXPECT_DOUBLE_EQ(*Row("A", 2, "dqn", 1, 0.6, 0.5).Ratio(), 1.2);
  EXPECT_FALSE(Row("A", 1, "dqn", 1, 0.0, 0.0).Ratio().has_value());
  EXPECT_FALSE(Row("A", 1, "dqn", 1, 0.3, -0.1).Ratio().has_value());
}

TEST(Optimality, MedianP10WorstAndShareAtOrAbove95PerAlgorithmAndUavCount) {
  const std::vector<OptimalitySummary> summary = SummarizeOptimality(OptimalityRows());
  ASSERT_EQ(summary.size(), 4u);  // sac has no ratio
  // dqn first (AllAlgorithms() order), then ppo by UAV count, then the unrecorded algorithm.
  EXPECT_EQ(summary[0].algorithm, "dqn");
  EXPECT_EQ(summary[0].uavs, 1);
  EXPECT_EQ(summary[0].runs, 5);
  EXPECT_EQ(summary[0].scenarios, 5);
  EXPECT_NEAR(summary[0].median, 0.97, 1e-12);
  EXPECT_NEAR(summary[0].p10, 0.5 + 0.4 * 0.4, 1e-12);  // (5 - 1) * 0.1 = 0.4 of 0.5 -> 0.9
  EXPECT_NEAR(summary[0].worst, 0.5, 1e-12);
  EXPECT_EQ(summary[0].near_optimal_runs, 3);  // 1.0, 0.99, 0.97
  EXPECT_DOUBLE_EQ(summary[0].NearOptimalShare(), 0.6);

  EXPECT_EQ(summary[1].algorithm, "ppo");
  EXPECT_EQ(summary[1].uavs, 1);
  EXPECT_EQ(summary[1].runs, 1);
  EXPECT_EQ(summary[1].near_optimal_runs, 1);  // 0.95 counts: "at or above"
  EXPECT_NEAR(summary[1].p10, 0.95, 1e-12);

  EXPECT_EQ(summary[2].algorithm, "ppo");
  EXPECT_EQ(summary[2].uavs, 2);
  EXPECT_EQ(summary[2].runs, 2);
  EXPECT_NEAR(summary[2].median, 0.98, 1e-12);
  EXPECT_NEAR(summary[2].p10, 0.94 + 0.1 * 0.08, 1e-12);
  EXPECT_NEAR(summary[2].worst, 0.94, 1e-12);
  EXPECT_EQ(summary[2].near_optimal_runs, 1);

  EXPECT_EQ(summary[3].algorithm, "");
  EXPECT_NEAR(summary[3].median, 0.8, 1e-12);
  EXPECT_TRUE(SummarizeOptimality({}).empty());
}

TEST(Optimality, RunsBelow95AreListedWorstFirst) {
  const std::vector<OptimalityRow> below = RunsBelowNearOptimal(OptimalityRows());
  ASSERT_EQ(below.size(), 4u);
  EXPECT_EQ(below[0].scenario, "D");   // 0.5
  EXPECT_EQ(below[1].algorithm, "");   // 0.8
  EXPECT_EQ(below[2].scenario, "C");   // 0.9
  EXPECT_EQ(below[3].scenario, "S3");  // 0.94
}

TEST(Optimality, TablesCsvJsonAndCdf) {
  const std::vector<OptimalityRow> rows = OptimalityRows();
  const std::vector<OptimalitySummary> summary = SummarizeOptimality(rows);
  const std::string text = FormatOptimalityText(summary);
  EXPECT_NE(text.find("algorithm  UAVs  runs  scenarios  median    P10  worst      >= 0.95"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("dqn           1     5          5   0.970  0.660  0.500   3/5 (60 %)"),
            std::string::npos)
      << text;
  EXPECT_NE(FormatOptimalityMarkdown(summary).find("| ppo | 2 | 2 | 2 | 0.980 | 0.948 | 0.940 | "
                                                   "1/2 (50 %) |"),
            std::string::npos)
      << FormatOptimalityMarkdown(summary);
  const std::string csv = FormatOptimalitySummaryCsv(summary);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "algorithm,uavs,runs,scenarios,median,p10,worst,near_optimal_runs,near_optimal_share,"
            "median_placement_s");
  EXPECT_NE(csv.find("\ndqn,1,5,5,0.97,0.66,0.5,3,0.6,\n"), std::string::npos) << csv;
  EXPECT_EQ(OptimalityToJson(summary)[2]["near_optimal_share"], 0.5);
  const std::string all = FormatOptimalityRowsCsv(rows);
  EXPECT_NE(all.find("\nS2,2,ppo,1,rl@ppo,1,1.02,1,1.02,\n"), std::string::npos) << all;
  EXPECT_NE(all.find("\nA,1,sac,1,rl@sac,1,0,0,,\n"), std::string::npos) << all;  // no ratio
  // The CDF per group: dqn's five ratios, P(ratio <= x) from 0.2 to 1.
  const std::string cdf = FormatOptimalityCdfCsv(rows);
  EXPECT_EQ(cdf.substr(0, cdf.find("ppo")),
            "algorithm,uavs,ratio,p\ndqn,1,0.5,0.2\ndqn,1,0.9,0.4\ndqn,1,0.97,0.6\n"
            "dqn,1,0.99,0.8\ndqn,1,1,1\n");
}

// A placement of a position job: a named policy's (rl+<name>) or another positioner's.
OptimalityRow Placed(const std::string& scenario, const std::string& label, double reward,
                     double oracle, double seconds) {
  OptimalityRow row;
  row.scenario = scenario;
  row.algorithm = label;
  row.label = label;
  row.runs = 1;
  row.rl_reward = reward;
  row.oracle_reward = oracle;
  row.placement_s = seconds;
  return row;
}

// Per-scenario training, a policy for any scenario and the other positioners side by side: the
// trained algorithms first, then the named policies, then the positioners (the oracle last),
// each with its median seconds per placement; the oracle's own placements are no curve of the
// CDF and no run to look at, and centroid's misses are not rl's.
TEST(Optimality, ZeroShotPerScenarioAndPositionersSideBySide) {
  std::vector<OptimalityRow> rows;
  for (const char* scenario : {"A", "B", "C"}) {
    OptimalityRow trained = Row(scenario, 1, "ppo", 1, 0.5, 0.5);
    trained.placement_s = scenario[0] == 'A' ? 30.0 : 40.0;
    rows.push_back(trained);
    rows.push_back(Placed(scenario, "oracle", 0.5, 0.5, 3.0));
    rows.push_back(Placed(scenario, "centroid", 0.3, 0.5, 1.0));
    rows.push_back(Placed(scenario, "rl+generalist", scenario[0] == 'C' ? 0.45 : 0.5, 0.5, 0.8));
  }
  const std::vector<OptimalitySummary> summary = SummarizeOptimality(rows);
  ASSERT_EQ(summary.size(), 4u);
  EXPECT_EQ(summary[0].algorithm, "ppo");
  EXPECT_DOUBLE_EQ(summary[0].median_placement_s, 40.0);
  EXPECT_EQ(summary[1].algorithm, "rl+generalist");
  EXPECT_NEAR(summary[1].median, 1.0, 1e-12);
  EXPECT_NEAR(summary[1].worst, 0.9, 1e-12);
  EXPECT_DOUBLE_EQ(summary[1].median_placement_s, 0.8);
  EXPECT_EQ(summary[2].algorithm, "centroid");
  EXPECT_EQ(summary[2].near_optimal_runs, 0);
  EXPECT_EQ(summary[3].algorithm, "oracle");
  EXPECT_DOUBLE_EQ(summary[3].median_placement_s, 3.0);
  EXPECT_NE(FormatOptimalityText(summary).find("0.8"), std::string::npos);
  EXPECT_NE(FormatOptimalityMarkdown(summary).find(" | 3/3 (100 %) | 40.0 |"), std::string::npos)
      << FormatOptimalityMarkdown(summary);
  EXPECT_EQ(OptimalityToJson(summary)[1]["median_placement_s"], 0.8);

  const std::vector<OptimalityCurve> cdf = OptimalityCdf(rows);
  ASSERT_EQ(cdf.size(), 3u);  // no oracle curve
  EXPECT_EQ(cdf[0].algorithm, "ppo");
  EXPECT_EQ(cdf[1].algorithm, "rl+generalist");
  EXPECT_EQ(cdf[2].algorithm, "centroid");
  EXPECT_EQ(FormatOptimalityCdfCsv(rows).find("oracle"), std::string::npos);

  const std::vector<OptimalityRow> below = RunsBelowNearOptimal(rows);
  ASSERT_EQ(below.size(), 1u);  // centroid's three are no rl run
  EXPECT_EQ(below[0].label, "rl+generalist");
  EXPECT_NE(FormatOptimalityRowsCsv(rows).find("\nC,1,centroid,0,centroid,1,0.3,0.5,0.6,1\n"),
            std::string::npos)
      << FormatOptimalityRowsCsv(rows);
}

TEST(Optimality, TheOracleAloneComparesNothing) {
  EXPECT_TRUE(SummarizeOptimality({Placed("A", "oracle", 0.5, 0.5, 1.0)}).empty());
  EXPECT_EQ(FormatOptimalitySection({Placed("A", "oracle", 0.5, 0.5, 1.0)}), "");
  EXPECT_EQ(SummarizeOptimality(
                {Placed("A", "oracle", 0.5, 0.5, 1.0), Placed("A", "centroid", 0.4, 0.5, 1.0)})
                .size(),
            2u);
}

TEST(Optimality, TheReportSectionIsAbsentWithoutRatios) {
  EXPECT_EQ(FormatOptimalitySection({}), "");
  EXPECT_EQ(FormatOptimalitySection({Row("A", 1, "sac", 1, 0.0, 0.0)}), "");
  const std::string section = FormatOptimalitySection(OptimalityRows());
  EXPECT_NE(section.find("## Optimality: each placement against the oracle"), std::string::npos);
  EXPECT_NE(section.find("### rl runs under 95 % of the oracle, worst first"), std::string::npos);
  EXPECT_NE(section.find("| D | 1 | dqn | 1 | rl@dqn | 0.2500 | 0.5000 | 0.500 | - |"),
            std::string::npos)
      << section;
}

// A campaign of scenarios B and C, runs 1-2, oracle and rl, algorithms dqn and sac, train
// seeds 1 and 2, whose evals record the rewards below.
class OptimalityStoreTest : public ::testing::Test {
 protected:
  OptimalityStoreTest() : campaign_(Campaign()), store_(dir_.File("rlpos.db")) {
    store_.ledger.Submit(campaign_);
  }

  static ExpandedCampaign Campaign() {
    const json document = {{"name", "optimality"},
                           {"scenarios", {"scenarios/b.json", "scenarios/c.json"}},
                           {"rng_runs", {1, 2}},
                           {"positioners", {"oracle", "rl"}},
                           {"train", {{"seeds", {1, 2}}, {"algorithms", {"sac", "dqn"}}}}};
    ExpandedCampaign campaign =
        ExpandCampaign(ParseCampaign(document, testing::SourcePath("campaigns")));
    campaign.use_cache = false;
    return campaign;
  }

  std::string Id(const std::string& key) const { return campaign_.id + "/" + key; }

  void Succeed(const std::string& key, const json& result) {
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1)) << key;
    ASSERT_EQ(store_.recorder.RecordSuccess(Id(key), 1, result), JobUpdate::kSucceeded) << key;
  }

  void Train(const std::string& scenario, const std::string& algorithm, int seed) {
    json result = testing::PositionResult(50, 35, 10 + seed);
    result["algorithm"] = algorithm;
    Succeed("train/" + scenario + "/" + algorithm + "/seed" + std::to_string(seed), result);
  }

  // An eval with `reward` (none: as recorded before the metric).
  void Eval(const std::string& scenario, const std::string& label, int run,
            std::optional<double> reward) {
    const std::string key = "eval/" + scenario + "/" + label + "/run" + std::to_string(run);
    json result = testing::EvalResult(run, 100, 2.0);
    if (reward)
      result["reward"] = *reward;
    Succeed(key, testing::AtJobPosition(store_.reader, Id(key), result));
  }

  void RecordResults() {
    for (const char* scenario : {"B", "C"}) {
      Succeed(std::string("position/") + scenario + "/oracle", testing::PositionResult(5, 50, 55));
      for (const char* algorithm : {"dqn", "sac"}) {
        Train(scenario, algorithm, 1);
        Train(scenario, algorithm, 2);
      }
    }
    for (int run : {1, 2}) {
      Eval("B", "oracle", run, 0.8);
      Eval("B", "rl@sac", run, 0.76);
      Eval("B", "rl@dqn@seed2", run, 0.8);
      Eval("C", "oracle", run, std::nullopt);  // no oracle reward: C has no ratio
      Eval("C", "rl@dqn", run, 0.5);
    }
    Eval("B", "rl@dqn", 1, 0.4);  // run 2 of it never came
  }

  testing::TempDir dir_;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

TEST_F(OptimalityStoreTest, OneRowPerLabelOfAScenarioWithAnOracleReward) {
  RecordResults();
  const std::vector<OptimalityRow> rows = store_.reader.Optimality(campaign_.id);
  ASSERT_EQ(rows.size(), 4u);  // B's three rl labels, then B's oracle; C has no oracle reward
  // The train jobs' order: dqn before sac, seeds as listed.
  EXPECT_EQ(rows[0].label, "rl@dqn");
  EXPECT_EQ(rows[0].algorithm, "dqn");
  EXPECT_EQ(rows[0].train_seed, 1u);
  EXPECT_EQ(rows[0].runs, 1);
  EXPECT_DOUBLE_EQ(rows[0].rl_reward, 0.4);
  EXPECT_DOUBLE_EQ(rows[0].oracle_reward, 0.8);
  EXPECT_DOUBLE_EQ(*rows[0].Ratio(), 0.5);
  EXPECT_EQ(rows[1].label, "rl@dqn@seed2");
  EXPECT_EQ(rows[1].train_seed, 2u);
  EXPECT_EQ(rows[1].runs, 2);
  EXPECT_DOUBLE_EQ(*rows[1].Ratio(), 1.0);
  EXPECT_EQ(rows[2].label, "rl@sac");
  EXPECT_EQ(rows[2].algorithm, "sac");
  EXPECT_DOUBLE_EQ(*rows[2].Ratio(), 0.95);
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(rows[i].trained && rows[i].IsRl()) << i;
  EXPECT_EQ(rows[3].label, "oracle");
  EXPECT_FALSE(rows[3].trained || rows[3].IsRl());
  EXPECT_DOUBLE_EQ(*rows[3].Ratio(), 1.0);
  for (const auto& row : rows) {
    EXPECT_EQ(row.scenario, "B");
    EXPECT_EQ(row.uavs, 1);
  }
}

TEST_F(OptimalityStoreTest, TheReportHasTheSectionItsFilesAndItsPlot) {
  RecordResults();
  const std::string out = dir_.File("report");
  ReportOptions options;
  options.plot_script = testing::SourcePath("scripts/plot_campaign.py");
  const ReportResult result = WriteReport(store_.reader, campaign_.id, out, options);
  const auto rows = store_.reader.Optimality(campaign_.id);
  EXPECT_EQ(testing::ReadFile(out + "/optimality.csv"), FormatOptimalityRowsCsv(rows));
  EXPECT_EQ(testing::ReadFile(out + "/optimality_summary.csv"),
            FormatOptimalitySummaryCsv(SummarizeOptimality(rows)));
  EXPECT_EQ(testing::ReadFile(out + "/optimality_cdf.csv"), FormatOptimalityCdfCsv(rows));
  const std::string md = testing::ReadFile(out + "/summary.md");
  EXPECT_NE(md.find(FormatOptimalitySection(rows)), std::string::npos) << md;
  EXPECT_NE(md.find("| dqn | 1 | 2 | 1 | 0.750 | 0.550 | 0.500 | 1/2 (50 %) |"), std::string::npos)
      << md;
  if (std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::is_regular_file(out + "/optimality_cdf.png"));
    EXPECT_TRUE(result.warnings.empty()) << result.warnings.front();
  }
}

// A named policy's evals have a row of their own, under their label as algorithm: no summary
// counts them with the trained rl of the scenario's algorithm. Beside them, centroid's and the
// oracle's, each with the seconds of the job that placed it (a cached job: its source's).
class OptimalityNamedPolicy : public ::testing::Test {
 protected:
  OptimalityNamedPolicy() : campaign_(NamedPolicyCampaign(dir_)), store_(dir_.File("rlpos.db")) {
    store_.ledger.Submit(campaign_);
  }

  // Scenario B placed by the oracle, centroid, trained rl and the named policy p1.
  static ExpandedCampaign NamedPolicyCampaign(const testing::TempDir& dir) {
    const std::string folder = dir.File("policies/p1");
    fs::create_directories(folder);
    testing::WriteFile(folder + "/scenario.json",
                       testing::ReadFile(testing::SourcePath("campaigns/scenarios/b.json")));
    testing::WriteFile(folder + "/result.json", R"({"algorithm": "dqn"})");
    testing::WriteFile(folder + "/policy.pt", "weights");
    const json document = {
        {"name", "named"},
        {"scenarios", {"scenarios/b.json"}},
        {"rng_runs", {1, 1}},
        {"positioners", {"oracle", "centroid", "rl", {{"rl", {{"policy", "policies/p1"}}}}}}};
    ExpandedCampaign campaign =
        ExpandCampaign(ParseCampaign(document, FileScenarioSource(testing::SourcePath("campaigns")),
                                     FilePolicySource(dir.path())));
    campaign.use_cache = false;
    return campaign;
  }

  void Succeed(const std::string& key, const json& result) {
    const std::string id = campaign_.id + "/" + key;
    ASSERT_TRUE(store_.ledger.MarkRunning(id, "w1", 0, 1)) << key;
    ASSERT_EQ(store_.recorder.RecordSuccess(id, 1, result), JobUpdate::kSucceeded) << key;
  }

  void Eval(const std::string& label, double reward) {
    const std::string key = "eval/B/" + label + "/run1";
    json result = testing::EvalResult(1, 100, 2.0);
    result["reward"] = reward;
    Succeed(key, testing::AtJobPosition(store_.reader, campaign_.id + "/" + key, result));
  }

  // The jobs' clocks, set by hand: the training 30 s, the policy's flight 0.5 s, centroid's
  // placement taken from another job of the cache (its own clock says 0.01 s).
  void SetClocks() {
    Database db(dir_.File("rlpos.db"), false, 1000);
    const auto clock = [&](const std::string& key, double started, double finished) {
      db.Exec("UPDATE jobs SET started_at = " + std::to_string(started) + ", finished_at = " +
              std::to_string(finished) + " WHERE id = '" + campaign_.id + "/" + key + "'");
    };
    clock("train/B/seed1", 100, 130);
    clock("position/B/rl+p1", 200, 200.5);
    clock("position/B/oracle", 300, 304);
    clock("position/B/centroid", 400, 400.01);
    db.Exec("UPDATE jobs SET cached_from = '" + campaign_.id + "/position/B/oracle' WHERE id = '" +
            campaign_.id + "/position/B/centroid'");
  }

  void RecordResults() {
    Succeed("position/B/oracle", testing::PositionResult(5, 50, 55));
    json trained = testing::PositionResult(50, 35, 11);
    trained["algorithm"] = "dqn";
    Succeed("train/B/seed1", trained);
    Succeed("position/B/rl+p1", testing::PositionResult(40, 30, 12));
    Succeed("position/B/centroid", testing::PositionResult(45, 40, 20));
    SetClocks();
    Eval("oracle", 0.8);
    Eval("centroid", 0.6);
    Eval("rl", 0.4);
    Eval("rl+p1", 0.8);
  }

  testing::TempDir dir_;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

TEST_F(OptimalityNamedPolicy, ANamedPolicyIsNeverCountedAsTrainedRl) {
  RecordResults();
  const std::vector<OptimalityRow> rows = store_.reader.Optimality(campaign_.id);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].label, "rl");
  EXPECT_EQ(rows[0].algorithm, "dqn");
  EXPECT_TRUE(rows[0].trained);
  EXPECT_DOUBLE_EQ(*rows[0].Ratio(), 0.5);
  EXPECT_NEAR(*rows[0].placement_s, 30.0, 1e-9);
  // The position jobs' placements, by label.
  std::map<std::string, const OptimalityRow*> by_label;
  for (const auto& row : rows)
    by_label[row.label] = &row;
  ASSERT_EQ(by_label.size(), 4u);
  const OptimalityRow& named = *by_label.at("rl+p1");
  EXPECT_EQ(named.algorithm, "rl+p1");
  EXPECT_EQ(named.train_seed, 0u);
  EXPECT_FALSE(named.trained);
  EXPECT_TRUE(named.IsRl());
  EXPECT_DOUBLE_EQ(*named.Ratio(), 1.0);
  EXPECT_NEAR(*named.placement_s, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(*by_label.at("centroid")->Ratio(), 0.75);
  EXPECT_NEAR(*by_label.at("centroid")->placement_s, 4.0, 1e-9);  // the cache's source's
  EXPECT_NEAR(*by_label.at("oracle")->placement_s, 4.0, 1e-9);
  const std::vector<OptimalitySummary> summary = SummarizeOptimality(rows);
  ASSERT_EQ(summary.size(), 4u);
  EXPECT_EQ(summary[0].algorithm, "dqn");
  EXPECT_EQ(summary[1].algorithm, "rl+p1");
  EXPECT_EQ(summary[2].algorithm, "centroid");
  EXPECT_EQ(summary[3].algorithm, "oracle");
}

}  // namespace
}  // namespace rlpos
