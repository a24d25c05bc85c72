// The eval metrics table (metrics/eval_metrics.h) against what is derived from it or written by
// hand beside it: the JSON an eval prints and its check, the SQL schema, the rows read back, the
// migrations of a new metric and the docs' table.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>

#include "common/metrics/eval_metrics.h"
#include "common/metrics/run_metrics.h"
#include "common/store/job_result.h"
#include "common/store/metric_columns.h"
#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "coordinator/reporting/results_format.h"
#include "coordinator/reporting/uav_summary.h"
#include "tests/support/campaign_fixtures.h"
#include "tests/support/store_migrations.h"

namespace rlpos {
namespace {

using testing::MigrateUpTo;

// "name TYPE [NOT NULL]" of each column of `table`, in order.
std::vector<std::string> Columns(Database& db, const std::string& table) {
  std::vector<std::string> out;
  Statement info = db.Prepare("SELECT name, type, \"notnull\" FROM pragma_table_info(?)");
  info.Bind(table);
  const ResultColumn name = info.Column("name"), type = info.Column("type"),
                     not_null = info.Column("notnull");
  while (info.Step())
    out.push_back(info.Text(name) + " " + info.Text(type) +
                  (info.Int(not_null) ? " NOT NULL" : ""));
  return out;
}

std::string ViewSql(Database& db, const std::string& view) {
  Statement select = db.Prepare("SELECT sql FROM sqlite_master WHERE name = ?");
  select.Bind(view);
  return select.Step() ? select.Text(select.Column("sql")) : "";
}

template <typename Def>
std::string Column(const char* name, const Def& m) {
  return std::string(name) + " " + m.SqlType() + (m.nullable ? "" : " NOT NULL");
}

// Today's metric columns, as schema 1 to 10 wrote them: existing files must keep reading.
TEST(MetricTable, SchemaColumnsAreTheTables) {
  testing::TempDir dir;
  Database db(dir.File("schema.db"), false, 1000);
  MigrateUpTo(db, LatestSchemaVersion());
  // Today's columns come first, unchanged; a metric added later comes after them.
  const std::vector<std::string> metrics = Columns(db, "metrics");
  ASSERT_GE(metrics.size(), 17u);
  EXPECT_EQ(std::vector<std::string>(metrics.begin(), metrics.begin() + 17),
            (std::vector<std::string>{
                "job_id TEXT", "campaign_id TEXT NOT NULL", "scenario TEXT NOT NULL",
                "label TEXT NOT NULL", "rng_run INTEGER NOT NULL",
                "aggregate_throughput_mbps REAL NOT NULL", "mean_delay_ms REAL", "loss_ratio REAL",
                "n_los INTEGER NOT NULL", "n_ues INTEGER NOT NULL", "demands_met INTEGER NOT NULL",
                "min_snr_db REAL", "x REAL NOT NULL", "y REAL NOT NULL", "z REAL NOT NULL",
                "worst_ue_throughput_mbps REAL", "jain_fairness REAL"}));
  const std::set<std::string> run(metrics.begin(), metrics.end());
  std::set<std::string> uav;
  for (const auto& c : Columns(db, "uav_metrics"))
    uav.insert(c);
  for (const auto& m : kEvalMetrics) {
    EXPECT_EQ(run.count(Column(m.key, m)), 1u) << m.key;
    if (m.HasUav()) {
      EXPECT_EQ(uav.count(Column(m.uav_key, m)), 1u) << m.uav_key;
    }
  }
  // Each view has a column of the metric's view name (Prepare throws for an unknown one).
  for (const auto& m : kEvalMetrics) {
    EXPECT_NO_THROW(db.Prepare(std::string("SELECT ") + m.RunView() + " FROM v_eval_runs"))
        << m.key;
    if (m.HasUav()) {
      EXPECT_NO_THROW(db.Prepare(std::string("SELECT ") + m.UavView() + " FROM v_eval_uavs"))
          << m.key;
    }
  }
}

TEST(MetricTable, TheRewardIsTheOneMetricNewerThanTheHandWrittenSchema) {
  // Version 11 adds the reward to metrics and v_eval_runs (a run's only: a UAV has none);
  // versions 12 and 13, hand-written after it, a named policy's hash on jobs and the track
  // jobs' tables; nothing is newer.
  const std::vector<Migration> derived = DerivedMetricMigrations();
  ASSERT_EQ(derived.size(), 1u);
  EXPECT_EQ(derived[0].version, kLastHandWrittenSchema + 1);
  EXPECT_EQ(LatestSchemaVersion(), kLastHandWrittenSchema + 3);
  EXPECT_EQ(std::size(kHandWrittenSchemasAfterMetrics), 2u);
  EXPECT_EQ(kHandWrittenSchemasAfterMetrics[0], kLastHandWrittenSchema + 2);
  EXPECT_EQ(kHandWrittenSchemasAfterMetrics[1], kLastHandWrittenSchema + 3);
  testing::TempDir dir;
  Database db(dir.File("reward.db"), false, 1000);
  MigrateUpTo(db, LatestSchemaVersion());
  EXPECT_EQ(Columns(db, "metrics").back(), "reward REAL");
  EXPECT_EQ(Columns(db, "uav_metrics").back(), "z REAL NOT NULL");
  EXPECT_NE(ViewSql(db, "v_eval_runs").find("m.jain_fairness, m.reward\nFROM"), std::string::npos);
}

RunMetrics TwoUavRun() {
  RunMetrics m;
  m.position = {1, 2, 3};
  m.window = {1, 11};
  m.run = 5;
  m.aggregate_throughput_mbps = 30;
  m.mean_delay_ms = 2.5;
  m.loss_ratio = 0.25;
  m.min_snr_db = 7;
  m.worst_ue_throughput_mbps = 10;
  m.jain_fairness = 0.9;
  m.n_los = 2;
  m.n_ues = 3;
  m.demands_met = 1;
  for (int u = 0; u < 2; ++u) {
    UavMetrics share;
    share.uav = {u == 0 ? "north" : "south", {1.0 + u, 2, 3}, 1 + u};
    share.throughput_mbps = u == 0 ? 20 : 10;
    share.mean_delay_ms = 2.5;
    share.loss_ratio = 0.25;
    share.worst_ue_throughput_mbps = 10;
    share.jain_fairness = u == 0 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
    share.n_los = 1;
    share.ues_served = u == 0 ? 2 : 1;
    m.uavs.push_back(share);
  }
  return m;
}

TEST(MetricTable, WhatAnEvalPrintsIsReadBackAsIs) {
  const RunMetrics m = TwoUavRun();
  const nlohmann::json json = ToJson(m);
  const EvalResult r = ParseEvalResult(json);
  ASSERT_EQ(r.uavs.size(), 2u);
  for (const auto& metric : kEvalMetrics) {
    if (metric.IsCount()) {
      EXPECT_EQ(json.at(metric.key), m.*metric.run_count) << metric.key;
    } else {
      EXPECT_EQ(json.at(metric.key), m.*metric.run_real) << metric.key;
    }
  }
  EXPECT_EQ(r.aggregate_throughput_mbps, 30.0);
  EXPECT_EQ(r.n_ues, 3);
  EXPECT_EQ(r.uavs[1].ues_served, 1);
  EXPECT_EQ(r.uavs[0].jain_fairness, 1.0);
  EXPECT_FALSE(r.uavs[1].jain_fairness.has_value());  // NaN is printed as null
  EXPECT_EQ(json.at("uavs").at(1).at("throughput_mbps"), 10.0);
}

TEST(MetricTable, ARangeOfTheTableRefusesAResult) {
  nlohmann::json json = ToJson(TwoUavRun());
  json["loss_ratio"] = 1.5;
  try {
    ParseEvalResult(json);
    FAIL() << "a loss ratio of 1.5 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "result \"loss_ratio\" is not in [0, 1]");
  }
  json = ToJson(TwoUavRun());
  json["uavs"][0]["jain_fairness"] = 0;
  EXPECT_THROW(ParseEvalResult(json), std::invalid_argument);
}

// What a metric declared with .Since(11) would get: its columns in the tables and views.
TEST(MetricTable, ANewMetricsColumnsAreAddedToTablesAndViews) {
  testing::TempDir dir;
  Database db(dir.File("new_metric.db"), false, 1000);
  MigrateUpTo(db, kLastHandWrittenSchema);
  const Migration added =
      AddMetricColumns(11, {{"REAL", "p95_delay_ms", "p95_delay", "p95_delay_ms", "p95_delay"}});
  EXPECT_EQ(added.version, 11);
  db.Exec(added.sql);
  added.convert(db);
  EXPECT_EQ(Columns(db, "metrics").back(), "p95_delay_ms REAL");
  EXPECT_EQ(Columns(db, "uav_metrics").back(), "p95_delay_ms REAL");
  EXPECT_NE(ViewSql(db, "v_eval_runs").find("m.jain_fairness, m.p95_delay_ms AS p95_delay\nFROM"),
            std::string::npos);
  EXPECT_NE(ViewSql(db, "v_eval_uavs").find("u.job_id, u.p95_delay_ms AS p95_delay\nFROM"),
            std::string::npos);
  // The views still work, and show the new column.
  Statement select = db.Prepare("SELECT COUNT(p95_delay) FROM v_eval_uavs");
  EXPECT_TRUE(select.Step());
}

TEST(MetricTable, TheDocsTableHasARowPerMetric) {
  const std::string markdown = EvalMetricsMarkdown();
  std::size_t lines = 0;
  for (const char c : markdown)
    lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, kEvalMetrics.size() + 2);  // header, rule
  for (const auto& m : kEvalMetrics)
    EXPECT_NE(markdown.find(std::string("`") + m.key + "`"), std::string::npos) << m.key;
  EXPECT_NE(markdown.find("| throughput | Mbit/s | `aggregate_throughput_mbps` (UAV: "
                          "`throughput_mbps`) |"),
            std::string::npos);
}

// The summaries' columns are written by hand: each mean the table declares must be among them.
TEST(MetricTable, TheSummariesShowTheMeansTheTableDeclares) {
  const auto has = [](const std::vector<std::string>& columns, const char* name) {
    return std::count(columns.begin(), columns.end(), name) == 1;
  };
  int means = 0;
  for (const auto& m : kEvalMetrics) {
    if (!m.mean_column)
      continue;
    ++means;
    EXPECT_TRUE(has(SummaryCsvColumns(), m.mean_column)) << m.mean_column;
    if (m.HasUav()) {
      EXPECT_TRUE(has(UavSummaryCsvColumns(), m.mean_column)) << m.mean_column;
    }
  }
  EXPECT_EQ(means, 2);
}

}  // namespace
}  // namespace rlpos
