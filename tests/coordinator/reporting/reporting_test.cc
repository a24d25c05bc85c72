// The reporting layer of `rlpos-campaign results` and `report`: summary numbers against values
// computed by hand, row order, the CSV / JSON / text renderings, the curves, and the report
// folder (files, errors, plots).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/hash/sha256.h"
#include "common/store/store_error.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/csv_cells.h"
#include "coordinator/reporting/distribution_curves.h"
#include "coordinator/reporting/report_writer.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/run_groups.h"
#include "coordinator/reporting/scenario_maps.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/campaign_fixtures.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// t(0.975, 1): the 95 % CI of the mean of two runs is t * s / sqrt(2).
constexpr double kT1 = 12.706204736174698;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    lines.push_back(line);
  return lines;
}

bool MatplotlibAvailable() {
  return std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0 ||
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

ReportOptions PlotWith(const std::string& script, const std::string& python = "") {
  ReportOptions options;
  options.plot_script = script;
  options.python = python;
  return options;
}

std::string ExeDir() {
  return fs::read_symlink("/proc/self/exe").parent_path().string();
}

// The mini campaign (scenarios B and C, runs 1-2, every positioner) with these eval results:
//   B baseline  run1 100 Mbit/s 4 ms, run2 120 Mbit/s 6 ms
//   B offset1   run1  90 Mbit/s 5.5 ms                       (one run: no CI)
//   B centroid  run1 100 Mbit/s 2 ms, run2 100 Mbit/s 2 ms   (ties)
//   B rl        run1 130 Mbit/s 3 ms, run2 150 Mbit/s no delay, 2 of 4 UEs in LoS
//   C oracle    run1  80 Mbit/s 1 ms                         (no baseline in C)
//   C centroid  run1 failed (both attempts)
class ReportingTest : public ::testing::Test {
 protected:
  ReportingTest() : campaign_(testing::MiniCampaign()), store_(dir_.File("rlpos.db")) {
    store_.ledger.Submit(campaign_);
  }

  std::string Id(const std::string& key) const { return campaign_.id + "/" + key; }

  void Produce(const std::string& key) {
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1)) << key;
    ASSERT_EQ(store_.recorder.RecordSuccess(Id(key), 1, testing::PositionResult(50, 35, 10)),
              JobUpdate::kSucceeded)
        << key;
  }

  void Eval(const std::string& scenario, const std::string& label, int run, double mbps,
            std::optional<double> delay_ms, int n_los = 4) {
    const std::string key = "eval/" + scenario + "/" + label + "/run" + std::to_string(run);
    json result = testing::EvalResult(run, mbps, delay_ms.value_or(0.0));
    if (!delay_ms)
      result["mean_delay_ms"] = nullptr;
    result["n_los"] = n_los;
    result = testing::AtJobPosition(store_.reader, Id(key), result);
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1)) << key;
    ASSERT_EQ(store_.recorder.RecordSuccess(Id(key), 1, result), JobUpdate::kSucceeded) << key;
  }

  void FailTwice(const std::string& key) {
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1));
    ASSERT_EQ(store_.ledger.RecordFailure(Id(key), 1, "exit code 1"), JobUpdate::kRetrying);
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 2));
    ASSERT_EQ(store_.ledger.RecordFailure(Id(key), 2, "exit code 1"), JobUpdate::kFailed);
  }

  void RecordResults() {
    Produce("position/B/baseline");
    Produce("position/B/centroid");
    Produce("train/B/seed1");
    Produce("position/C/oracle");
    Produce("position/C/centroid");
    // Recorded out of report order on purpose.
    Eval("C", "oracle", 1, 80, 1.0);
    Eval("B", "rl", 1, 130, 3.0);
    Eval("B", "rl", 2, 150, std::nullopt, 2);
    Eval("B", "centroid", 1, 100, 2.0);
    Eval("B", "centroid", 2, 100, 2.0);
    Eval("B", "baseline", 2, 120, 6.0);
    Eval("B", "baseline", 1, 100, 4.0);
    Eval("B", "offset1", 1, 90, 5.5);
    FailTwice("eval/C/centroid/run1");
  }

  testing::TempDir dir_;
  ExpandedCampaign campaign_;
  CoordinatorStore store_;
};

// --- Order ---

TEST(ReportOrder, LabelsFollowThePaper) {
  std::vector<std::string> labels{"rl@seed10", "rl",       "oracle",        "zeta",
                                  "offset2",   "centroid", "offset2@seed2", "offset1",
                                  "baseline",  "rl@seed2", "alpha"};
  std::sort(labels.begin(), labels.end(), ReportLabelLess);
  EXPECT_EQ(labels,
            (std::vector<std::string>{"baseline", "offset1", "offset2", "offset2@seed2", "centroid",
                                      "oracle", "rl", "rl@seed2", "rl@seed10", "alpha", "zeta"}));
}

TEST(ReportOrder, AlgorithmsFollowTheirPlainLabelEachWithItsSeeds) {
  std::vector<std::string> labels{"rl@sac",        "rl@dqn@seed2", "offset1@ppo", "rl@dqn",
                                  "rl@ppo@seed10", "rl@ppo",       "offset1@dqn", "rl@ppo@seed2",
                                  "oracle",        "rl@a2c"};
  std::sort(labels.begin(), labels.end(), ReportLabelLess);
  EXPECT_EQ(labels, (std::vector<std::string>{"offset1@dqn", "offset1@ppo", "oracle", "rl@dqn",
                                              "rl@dqn@seed2", "rl@ppo", "rl@ppo@seed2",
                                              "rl@ppo@seed10", "rl@sac", "rl@a2c"}));
}

TEST(ReportOrder, ScenariosKeepTheOrderOfTheRows) {
  std::vector<MetricRow> rows;
  for (const char* scenario : {"Z", "A"}) {
    for (const char* label : {"rl@seed2", "baseline", "rl", "centroid"}) {
      MetricRow row;
      row.scenario = scenario;
      row.label = label;
      row.aggregate_throughput_mbps = 1;
      rows.push_back(row);
    }
  }
  std::vector<std::string> order;
  for (const auto& s : SummarizeRuns(rows))
    order.push_back(s.scenario + "/" + s.positioner);
  EXPECT_EQ(order, (std::vector<std::string>{"Z/baseline", "Z/centroid", "Z/rl", "Z/rl@seed2",
                                             "A/baseline", "A/centroid", "A/rl", "A/rl@seed2"}));
}

// --- Summary numbers ---

// A summary's run count and throughput statistics: mean, median and the half-width of its 95 % CI.
void ExpectThroughput(const PositionerSummary& s, int runs, double mean, double median,
                      double ci95) {
  EXPECT_EQ(s.runs, runs);
  EXPECT_DOUBLE_EQ(s.throughput_mean_mbps, mean);
  EXPECT_DOUBLE_EQ(s.throughput_median_mbps, median);
  EXPECT_NEAR(s.throughput_ci95_mbps, ci95, 1e-9);
}

// How many of a summary's runs had a delay and how many had none, and the delays' mean.
void ExpectDelays(const PositionerSummary& s, int runs, int null_runs, double mean_ms) {
  EXPECT_EQ(s.delay_runs, runs);
  EXPECT_EQ(s.delay_null_runs, null_runs);
  ASSERT_TRUE(s.delay_mean_ms.has_value());
  EXPECT_DOUBLE_EQ(*s.delay_mean_ms, mean_ms);
}

TEST_F(ReportingTest, SummaryMatchesHandComputedValues) {
  RecordResults();
  const auto summary = SummarizeCampaign(store_.reader, campaign_.id);
  std::vector<std::string> order;
  for (const auto& s : summary)
    order.push_back(s.scenario + "/" + s.positioner);
  ASSERT_EQ(order, (std::vector<std::string>{"B/baseline", "B/offset1", "B/centroid", "B/rl",
                                             "C/oracle"}));

  const PositionerSummary& base = summary[0];
  // s = sqrt(((100 - 110)^2 + (120 - 110)^2) / 1) = 10 sqrt(2); s / sqrt(2) = 10.
  ExpectThroughput(base, 2, 110.0, 110.0, kT1 * 10.0);
  ExpectDelays(base, 2, 0, 5.0);
  EXPECT_NEAR(base.delay_ci95_ms, kT1 * 1.0, 1e-9);  // s = sqrt(2), s / sqrt(2) = 1
  EXPECT_DOUBLE_EQ(base.nlos_ratio_mean, 1.0);
  EXPECT_DOUBLE_EQ(base.demands_met_mean, 3.0);
  EXPECT_DOUBLE_EQ(base.ues_mean, 4.0);
  ASSERT_TRUE(base.throughput_change_pct.has_value());
  EXPECT_DOUBLE_EQ(*base.throughput_change_pct, 0.0);
  EXPECT_DOUBLE_EQ(*base.delay_change_pct, 0.0);

  const PositionerSummary& offset1 = summary[1];
  EXPECT_EQ(offset1.runs, 1);
  EXPECT_DOUBLE_EQ(offset1.throughput_median_mbps, 90.0);
  EXPECT_TRUE(std::isnan(offset1.throughput_ci95_mbps));
  EXPECT_TRUE(std::isnan(offset1.delay_ci95_ms));
  EXPECT_NEAR(*offset1.throughput_change_pct, 100.0 * (90.0 - 110.0) / 110.0, 1e-12);
  EXPECT_NEAR(*offset1.delay_change_pct, 10.0, 1e-12);  // 5.5 vs 5

  const PositionerSummary& centroid = summary[2];
  EXPECT_DOUBLE_EQ(centroid.throughput_ci95_mbps, 0.0);  // identical runs
  EXPECT_NEAR(*centroid.delay_change_pct, -60.0, 1e-12);

  const PositionerSummary& rl = summary[3];
  ExpectThroughput(rl, 2, 140.0, 140.0, kT1 * 10.0);
  ExpectDelays(rl, 1, 1, 3.0);
  EXPECT_TRUE(std::isnan(rl.delay_ci95_ms));
  EXPECT_DOUBLE_EQ(rl.nlos_ratio_mean, 0.75);  // (4/4 + 2/4) / 2
  EXPECT_NEAR(*rl.throughput_change_pct, 100.0 * 30.0 / 110.0, 1e-12);
  EXPECT_NEAR(*rl.delay_change_pct, -40.0, 1e-12);

  const PositionerSummary& oracle = summary[4];
  EXPECT_EQ(oracle.scenario, "C");
  EXPECT_FALSE(oracle.throughput_change_pct.has_value());  // C has no baseline
  EXPECT_FALSE(oracle.delay_change_pct.has_value());
}

TEST_F(ReportingTest, MedianOfThreeRunsIsTheMiddleOne) {
  std::vector<MetricRow> rows(3);
  const double mbps[] = {10, 40, 13};
  for (int i = 0; i < 3; ++i) {
    rows[i].scenario = "S";
    rows[i].label = "rl";
    rows[i].aggregate_throughput_mbps = mbps[i];
  }
  const auto summary = SummarizeRuns(rows);
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_DOUBLE_EQ(summary[0].throughput_median_mbps, 13.0);
  EXPECT_DOUBLE_EQ(summary[0].throughput_mean_mbps, 21.0);
  EXPECT_FALSE(summary[0].delay_mean_ms.has_value());  // no run has a delay
  EXPECT_EQ(summary[0].delay_null_runs, 3);
  EXPECT_TRUE(std::isnan(summary[0].nlos_ratio_mean));  // n_ues = 0
}

TEST_F(ReportingTest, EmptyAndUnknownCampaigns) {
  EXPECT_TRUE(SummarizeCampaign(store_.reader, campaign_.id).empty());
  EXPECT_THROW(SummarizeCampaign(store_.reader, "nope"), StoreError);
  EXPECT_THROW(WriteReport(store_.reader, "nope", dir_.File("out")), StoreError);
  EXPECT_FALSE(fs::exists(dir_.File("out")));
}

// --- Renderings ---

TEST(CsvCells, QuotesAndNumbers) {
  EXPECT_EQ(CsvText("B"), "B");
  EXPECT_EQ(CsvText("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvText("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvNumber(120.5), "120.5");
  EXPECT_EQ(CsvNumber(0.1), "0.1");
  EXPECT_EQ(CsvNumber(100.0 / 3.0), "33.333333333333336");  // round-trips
  EXPECT_EQ(CsvNumber(std::nan("")), "");
  EXPECT_EQ(CsvNumber(std::optional<double>()), "");
}

TEST_F(ReportingTest, CsvHasOneRowPerPositionerAndEmptyCellsForAbsentValues) {
  RecordResults();
  const auto lines = Lines(FormatSummaryCsv(SummarizeCampaign(store_.reader, campaign_.id)));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0],
            "scenario,positioner,runs,throughput_median_mbps,throughput_mean_mbps,"
            "throughput_ci95_mbps,delay_runs,delay_null_runs,delay_mean_ms,delay_ci95_ms,"
            "nlos_ratio_mean,demands_met_mean,ues_mean,worst_ue_mean_mbps,jain_mean,"
            "throughput_change_pct,delay_change_pct");
  // The t quantile is computed numerically: compare the CI cells as numbers.
  std::vector<std::string> cells;
  std::istringstream row(lines[1]);
  for (std::string cell; std::getline(row, cell, ',');)
    cells.push_back(cell);
  ASSERT_EQ(cells.size(), 17u) << lines[1];
  EXPECT_NEAR(std::stod(cells[5]), kT1 * 10.0, 1e-9);
  EXPECT_NEAR(std::stod(cells[9]), kT1, 1e-9);
  cells[5] = cells[9] = "ci";
  // No worst UE or fairness: these results are of the form before schema 9.
  EXPECT_EQ(CsvLine(cells), "B,baseline,2,110,110,ci,2,0,5,ci,1,3,4,,,0,0\n");
  EXPECT_EQ(lines[2], "B,offset1,1,90,90,,1,0,5.5,,1,3,4,,," +
                          CsvNumber(100.0 * (90.0 - 110.0) / 110.0) + "," +
                          CsvNumber(100.0 * (5.5 - 5.0) / 5.0));
  EXPECT_EQ(lines[4].rfind("B,rl,2,140,140,", 0), 0u) << lines[4];
  EXPECT_EQ(lines[5], "C,oracle,1,80,80,,1,0,1,,1,3,4,,,,");
}

TEST_F(ReportingTest, WorstUeAndFairnessAreStoredAndAveraged) {
  Produce("position/B/baseline");
  for (int run = 1; run <= 2; ++run) {
    const std::string key = "eval/B/baseline/run" + std::to_string(run);
    json result = testing::EvalResult(run, 100, 4.0);
    result["worst_ue_throughput_mbps"] = run == 1 ? 10.0 : 20.0;
    result["jain_fairness"] = run == 1 ? json(0.5) : json(nullptr);  // run 2: nothing received
    result = testing::AtJobPosition(store_.reader, Id(key), result);
    ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1));
    ASSERT_EQ(store_.recorder.RecordSuccess(Id(key), 1, result), JobUpdate::kSucceeded);
  }
  EXPECT_EQ(testing::QueryOne(store_.db.file(),
                              "SELECT group_concat(worst_ue_mbps || '/' || "
                              "IFNULL(jain_fairness, 'null'), ' ') FROM (SELECT * "
                              "FROM v_eval_runs ORDER BY rng_run)"),
            "10.0/0.5 20.0/null");
  const auto summary = SummarizeCampaign(store_.reader, campaign_.id);
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_DOUBLE_EQ(summary[0].worst_ue_mean_mbps.value_or(-1), 15.0);
  EXPECT_DOUBLE_EQ(summary[0].jain_mean.value_or(-1), 0.5);  // over the runs that have one
  // Implausible values from the network are refused.
  const std::string key = "eval/C/oracle/run1";
  Produce("position/C/oracle");
  json result = testing::AtJobPosition(store_.reader, Id(key), testing::EvalResult(1, 100, 4.0));
  result["jain_fairness"] = 1.5;
  ASSERT_TRUE(store_.ledger.MarkRunning(Id(key), "w1", 0, 1));
  EXPECT_NE(store_.recorder.RecordSuccess(Id(key), 1, result), JobUpdate::kSucceeded);
}

TEST_F(ReportingTest, JsonHasNullForAbsentValues) {
  RecordResults();
  const json j = SummaryToJson(SummarizeCampaign(store_.reader, campaign_.id));
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 5u);
  EXPECT_EQ(j[0]["scenario"], "B");
  EXPECT_EQ(j[0]["positioner"], "baseline");
  EXPECT_TRUE(j[0]["runs"].is_number_integer());
  EXPECT_EQ(j[0]["runs"], 2);
  EXPECT_NEAR(j[0]["throughput_ci95_mbps"].get<double>(), kT1 * 10.0, 1e-9);
  EXPECT_TRUE(j[1]["throughput_ci95_mbps"].is_null());  // one run
  EXPECT_EQ(j[3]["delay_null_runs"], 1);
  EXPECT_DOUBLE_EQ(j[3]["delay_change_pct"].get<double>(), -40.0);
  EXPECT_TRUE(j[4]["throughput_change_pct"].is_null());  // no baseline
  EXPECT_TRUE(j[4]["delay_change_pct"].is_null());
  std::vector<std::string> keys;
  for (const auto& item : j[0].items())
    keys.push_back(item.key());
  std::vector<std::string> columns = SummaryCsvColumns();
  std::sort(columns.begin(), columns.end());
  EXPECT_EQ(keys, columns);  // nlohmann::json orders keys by name
  EXPECT_EQ(SummaryToJson({}), json::array());
}

TEST_F(ReportingTest, TextTableIsAlignedAndRounded) {
  RecordResults();
  const auto lines = Lines(FormatSummaryText(SummarizeCampaign(store_.reader, campaign_.id)));
  ASSERT_EQ(lines.size(), 7u);  // header, rule, 5 rows
  EXPECT_EQ(lines[0].rfind("scenario  positioner  runs", 0), 0u) << lines[0];
  EXPECT_NE(lines[2].find("110.00"), std::string::npos) << lines[2];
  EXPECT_NE(lines[2].find("127.06"), std::string::npos) << lines[2];  // CI half width
  EXPECT_NE(lines[5].find("+27.3"), std::string::npos) << lines[5];   // rl vs baseline
  EXPECT_NE(lines[5].find("-40.0"), std::string::npos) << lines[5];
  EXPECT_EQ(lines[6].rfind("C         oracle", 0), 0u) << lines[6];
  EXPECT_EQ(lines[6].substr(lines[6].size() - 1), "-");  // no baseline
  // Every column starts where its header does: "mean Mbit/s" is right-aligned under its title.
  const std::size_t end = lines[0].find("mean Mbit/s") + std::string("mean Mbit/s").size();
  for (std::size_t i = 2; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i][end], ' ') << lines[i];
    EXPECT_NE(lines[i][end - 1], ' ') << lines[i];
  }
  EXPECT_EQ(Lines(FormatSummaryText({})).size(), 2u);
  const auto markdown =
      Lines(FormatSummaryMarkdown(SummarizeCampaign(store_.reader, campaign_.id)));
  ASSERT_EQ(markdown.size(), 7u);
  EXPECT_EQ(markdown[1].rfind("|---|---|---:|", 0), 0u);
  EXPECT_EQ(markdown[2].rfind("| B | baseline | 2 | 110.00 |", 0), 0u) << markdown[2];
}

// --- Curves ---

TEST_F(ReportingTest, CurvesPerScenarioAndPositioner) {
  RecordResults();
  const auto rows = store_.reader.Metrics(campaign_.id);
  const auto ccdf = ThroughputCcdf(rows);
  std::vector<std::string> points;
  for (const auto& p : ccdf) {
    points.push_back(p.scenario + "/" + p.positioner + " " + CsvNumber(p.x) + " " + CsvNumber(p.p));
  }
  EXPECT_EQ(points, (std::vector<std::string>{"B/baseline 100 0.5", "B/baseline 120 0",
                                              "B/offset1 90 0", "B/centroid 100 0", "B/rl 130 0.5",
                                              "B/rl 150 0", "C/oracle 80 0"}));
  const auto cdf = DelayCdf(rows);
  points.clear();
  for (const auto& p : cdf) {
    points.push_back(p.scenario + "/" + p.positioner + " " + CsvNumber(p.x) + " " + CsvNumber(p.p));
  }
  EXPECT_EQ(points, (std::vector<std::string>{"B/baseline 4 0.5", "B/baseline 6 1",
                                              "B/offset1 5.5 1", "B/centroid 2 1",
                                              "B/rl 3 1",  // the run without delay is left out
                                              "C/oracle 1 1"}));
  const auto ccdf_csv = Lines(FormatThroughputCcdfCsv(ccdf));
  ASSERT_EQ(ccdf_csv.size(), 8u);
  EXPECT_EQ(ccdf_csv[0], "scenario,positioner,throughput_mbps,p_above");
  EXPECT_EQ(ccdf_csv[1], "B,baseline,100,0.5");
  const auto cdf_csv = Lines(FormatDelayCdfCsv(cdf));
  ASSERT_EQ(cdf_csv.size(), 7u);
  EXPECT_EQ(cdf_csv[0], "scenario,positioner,delay_ms,p_at_most");
  EXPECT_EQ(cdf_csv[5], "B,rl,3,1");
}

// --- The report folder ---

TEST_F(ReportingTest, WriteReportWritesEveryFile) {
  RecordResults();
  const std::string out = dir_.File("reports/mini");  // parents are created too
  const ReportResult result = WriteReport(store_.reader, campaign_.id, out);
  const std::vector<std::string> names{"summary.csv", "summary.md", "throughput_ccdf.csv",
                                       "delay_cdf.csv"};
  ASSERT_EQ(result.files.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(result.files[i], out + "/" + names[i]);
    EXPECT_TRUE(fs::is_regular_file(result.files[i])) << result.files[i];
  }
  EXPECT_TRUE(result.warnings.empty());  // no plot script asked for: no plots, no warning
  const auto rows = store_.reader.Metrics(campaign_.id);
  const auto summary = SummarizeRuns(rows);
  EXPECT_EQ(testing::ReadFile(out + "/summary.csv"), FormatSummaryCsv(summary));
  EXPECT_EQ(testing::ReadFile(out + "/throughput_ccdf.csv"),
            FormatThroughputCcdfCsv(ThroughputCcdf(rows)));
  EXPECT_EQ(testing::ReadFile(out + "/delay_cdf.csv"), FormatDelayCdfCsv(DelayCdf(rows)));
  const std::string md = testing::ReadFile(out + "/summary.md");
  EXPECT_NE(md.find("# Campaign report: mini"), std::string::npos);
  EXPECT_NE(md.find("`" + campaign_.id + "`"), std::string::npos);
  EXPECT_NE(md.find("44 in all: 13 succeeded, 1 failed"), std::string::npos) << md;
  EXPECT_NE(md.find("1 job failed"), std::string::npos) << md;
  EXPECT_NE(md.find(FormatSummaryMarkdown(summary)), std::string::npos);
  // Nothing but the report: no temporary file left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 4);

  // Again over the existing files: replaced, not appended to.
  WriteReport(store_.reader, campaign_.id, out);
  EXPECT_EQ(testing::ReadFile(out + "/summary.csv"), FormatSummaryCsv(summary));
}

TEST_F(ReportingTest, EmptyCampaignWritesHeadersOnly) {
  const std::string out = dir_.File("empty");
  const ReportResult result = WriteReport(
      store_.reader, campaign_.id, out, PlotWith(testing::SourcePath("scripts/plot_campaign.py")));
  EXPECT_EQ(result.files.size(), 4u);  // no curve: the plot script is not even run
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(Lines(testing::ReadFile(out + "/summary.csv")).size(), 1u);
  EXPECT_EQ(testing::ReadFile(out + "/throughput_ccdf.csv"),
            "scenario,positioner,throughput_mbps,p_above\n");
  EXPECT_EQ(testing::ReadFile(out + "/delay_cdf.csv"), "scenario,positioner,delay_ms,p_at_most\n");
  const std::string md = testing::ReadFile(out + "/summary.md");
  EXPECT_NE(md.find("No eval run has succeeded yet."), std::string::npos);
  EXPECT_EQ(md.find("failed (see"), std::string::npos);  // no failure note
}

TEST_F(ReportingTest, OutDirThatCannotBeCreatedIsAnErrorNamingIt) {
  testing::WriteFile(dir_.File("a_file"), "x");
  const std::string out = dir_.File("a_file/report");
  try {
    WriteReport(store_.reader, campaign_.id, out);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(out), std::string::npos) << error.what();
  }
}

TEST_F(ReportingTest, MissingPlotScriptIsAWarning) {
  RecordResults();
  const std::string out = dir_.File("report");
  const std::string script = dir_.File("no/plot_campaign.py");
  const ReportResult result = WriteReport(store_.reader, campaign_.id, out, PlotWith(script));
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find(script), std::string::npos) << result.warnings[0];
  EXPECT_EQ(result.files.size(), 4u);
  EXPECT_TRUE(fs::is_regular_file(out + "/summary.csv"));
  EXPECT_TRUE(fs::is_regular_file(out + "/summary.md"));
  EXPECT_TRUE(fs::is_regular_file(out + "/throughput_ccdf.csv"));
  EXPECT_TRUE(fs::is_regular_file(out + "/delay_cdf.csv"));
}

TEST_F(ReportingTest, FailingInterpreterOrScriptIsAWarning) {
  RecordResults();
  const ReportOptions no_python =
      PlotWith(testing::SourcePath("scripts/plot_campaign.py"), dir_.File("no-such-python"));
  ReportResult result = WriteReport(store_.reader, campaign_.id, dir_.File("r1"), no_python);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("no-such-python"), std::string::npos) << result.warnings[0];
  EXPECT_EQ(result.files.size(), 4u);

  testing::WriteFile(dir_.File("broken.py"), "import sys\nprint('boom')\nsys.exit(1)\n");
  result =
      WriteReport(store_.reader, campaign_.id, dir_.File("r2"), PlotWith(dir_.File("broken.py")));
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("boom"), std::string::npos) << result.warnings[0];
  EXPECT_NE(result.warnings[0].find("exit status 1"), std::string::npos) << result.warnings[0];
  EXPECT_TRUE(fs::is_regular_file(dir_.File("r2/summary.csv")));
}

// A map per scenario, drawn by the rlpos-sim built beside the tests, with the rl flight of the
// train job's trajectory.csv.
TEST_F(ReportingTest, MapPerScenarioWithTheRlFlight) {
  Produce("position/B/baseline");
  Produce("position/C/oracle");
  const std::string trajectory =
      "episode,step,uav,action,x,y,z,n_los,throughput_mbps,reward\n"
      "2,1,0,backward,50,45,25,1,10,0.1\n2,2,0,down,50,45,20,1,10,0.1\n"
      "2,3,0,backward,50,40,20,1,10,0.1\n2,4,0,backward,50,35,10,2,20,0.2\n";
  ASSERT_TRUE(store_.ledger.MarkRunning(Id("train/B/seed1"), "w1", 0, 1));
  ASSERT_EQ(store_.recorder.RecordSuccess(
                Id("train/B/seed1"), 1, testing::PositionResult(50, 35, 10), "", nullptr,
                {ArtifactFile{"trajectory.csv", Sha256Hex(trajectory), trajectory}}),
            JobUpdate::kSucceeded);
  Eval("B", "baseline", 1, 100, 4.0);
  Eval("B", "rl", 1, 130, 3.0);
  Eval("B", "offset1", 1, 90, 5.5);
  Eval("C", "oracle", 1, 80, 1.0);
  ReportOptions options;
  options.render_program = DefaultRenderProgram(RLPOS_BIN_DIR);
  const std::string out = dir_.File("report");
  const ReportResult result = WriteReport(store_.reader, campaign_.id, out, options);
  for (const auto& w : result.warnings)
    ADD_FAILURE() << "warning: " << w;
  for (const char* map : {"map_1.png", "map_2.png"}) {
    const std::string png = testing::ReadFile((fs::path(out) / map).string());
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n") << map;
    EXPECT_NE(std::find(result.files.begin(), result.files.end(), (fs::path(out) / map).string()),
              result.files.end());
  }
  EXPECT_FALSE(fs::exists(fs::path(out) / "map_3.png"));
  const std::string md = testing::ReadFile((fs::path(out) / "summary.md").string());
  EXPECT_NE(md.find("### Scenario B\n\n![Scenario B](map_1.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("### Scenario C\n\n![Scenario C](map_2.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("The rl flight"), std::string::npos) << md;
}

// Without rlpos-sim the report is written all the same, with a warning for the maps.
TEST_F(ReportingTest, MissingRenderProgramIsAWarning) {
  ReportOptions options;
  options.render_program = dir_.File("no-such-rlpos-sim");
  const ReportResult result = WriteReport(store_.reader, campaign_.id, dir_.File("r"), options);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("no maps"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_.File("r") + "/summary.md"));
}

TEST(ReportPlots, DefaultPlotScriptIsCopiedBesideTheBinaries) {
  EXPECT_EQ(DefaultPlotScript("/opt/rlpos/bin"), "/opt/rlpos/bin/../share/rlpos/plot_campaign.py");
  const std::string script = DefaultPlotScript(ExeDir());
  ASSERT_TRUE(fs::is_regular_file(script)) << script;
  EXPECT_EQ(testing::ReadFile(script),
            testing::ReadFile(testing::SourcePath("scripts/plot_campaign.py")));
}

TEST_F(ReportingTest, PlotsArePngsWhenMatplotlibIsThere) {
  if (!MatplotlibAvailable())
    GTEST_SKIP() << "python3 with matplotlib not found";
  RecordResults();
  const std::string out = dir_.File("report with space");
  const ReportResult result =
      WriteReport(store_.reader, campaign_.id, out, PlotWith(DefaultPlotScript(ExeDir())));
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0];
  // B and C: one throughput CCDF and one delay CDF each.
  const std::vector<std::string> pngs{"throughput_ccdf_B.png", "delay_cdf_B.png",
                                      "throughput_ccdf_C.png", "delay_cdf_C.png"};
  ASSERT_EQ(result.files.size(), 4u + pngs.size());
  for (std::size_t i = 0; i < pngs.size(); ++i) {
    const std::string file = out + "/" + pngs[i];
    EXPECT_EQ(result.files[4 + i], file);
    ASSERT_TRUE(fs::is_regular_file(file)) << file;
    EXPECT_GT(fs::file_size(file), 1000u) << file;
    EXPECT_EQ(testing::ReadFile(file).substr(1, 3), "PNG") << file;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 8);
}

}  // namespace
}  // namespace rlpos
