// Track intervals read back as InsertTrackRun wrote them: scenarios in campaign order (not by
// name), then positioner, run and interval; and, for the page's map, only each scenario and
// positioner's first run.
#include "common/store/track_rows.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "common/store/schema.h"
#include "common/store/sqlite_db.h"
#include "tests/support/temp_dir.h"

namespace rlpos {
namespace {

void AddJob(Database& db, const std::string& id, int seq, const std::string& scenario) {
  db.Exec(
      "INSERT INTO jobs (id, campaign_id, seq, kind, key, scenario, label, state, attempt, "
      "max_attempts, timeout_s, created_at, position_rule_json) VALUES ('" +
      id + "', 'c0ffee', " + std::to_string(seq) + ", 'track', '" + id + "', '" + scenario +
      "', 'x', 'succeeded', 1, 2, 300, 1000, '{}')");
}

TrackRunResult TwoIntervals(std::uint64_t rng_run, double x) {
  TrackRunResult run;
  run.positioner = "oracle-track";
  run.fidelity = "analytic";
  run.run = rng_run;
  run.duration_s = 2.0;
  run.decision_interval_s = 1.0;
  run.scored_intervals = 2;
  for (int i = 0; i < 2; ++i) {
    TrackIntervalRow row;
    row.time_s = i + 1.0;
    row.reward = 0.5 + 0.1 * i + 0.01 * static_cast<double>(rng_run);
    row.throughput_mbps = 10.0 * (i + 1);
    row.delay_ms = i == 0 ? std::nullopt : std::optional<double>(3.5);
    row.los_share = 0.75;
    row.demands_met_share = 0.5;
    row.positions = {{x + i, 2.0, 30.0}, {x, -4.5, 45.0}};
    run.intervals.push_back(row);
  }
  return run;
}

// Scenario "z" comes first in the campaign, "a" second; "z" has runs 3 and 2.
void AddThreeRuns(Database& db) {
  MigrateSchema(db);
  db.Exec(
      "INSERT INTO campaigns (id, name, spec_json, created_at, state, max_attempts, "
      "job_timeout_s) VALUES ('c0ffee', 'walk', '{}', 1000, 'active', 2, 300)");
  const std::vector<std::tuple<std::string, std::string, std::int64_t, double>> runs{
      {"j1", "z", 3, 100.0}, {"j2", "z", 2, 200.0}, {"j3", "a", 1, 300.0}};
  int seq = 0;
  for (const auto& [job, scenario, rng_run, x] : runs) {
    AddJob(db, job, ++seq, scenario);
    InsertTrackRun(db, {job, "c0ffee", scenario, "oracle-track", rng_run},
                   TwoIntervals(static_cast<std::uint64_t>(rng_run), x));
  }
}

TEST(TrackIntervals, ReadInCampaignOrderWithTheirPositionsAndTheFirstRunAlone) {
  testing::TempDir dir;
  Database db(dir.File("store.db"), false, 1000);
  AddThreeRuns(db);

  const auto all = ReadTrackIntervalRows(db, "c0ffee", TrackRunsRead::kAll);
  ASSERT_EQ(all.size(), 6u);
  std::vector<std::string> order;
  for (const auto& r : all)
    order.push_back(r.scenario + std::to_string(r.rng_run) + "/" + std::to_string(r.interval));
  EXPECT_EQ(order, (std::vector<std::string>{"z2/0", "z2/1", "z3/0", "z3/1", "a1/0", "a1/1"}));
  const TrackIntervalRecord& second = all[1];
  EXPECT_EQ(second.label, "oracle-track");
  EXPECT_DOUBLE_EQ(second.row.time_s, 2.0);
  EXPECT_DOUBLE_EQ(second.row.reward, 0.62);
  EXPECT_DOUBLE_EQ(second.row.throughput_mbps, 20.0);
  EXPECT_EQ(second.row.delay_ms, std::optional<double>(3.5));
  EXPECT_FALSE(all[0].row.delay_ms.has_value()) << "a null delay stays absent";
  ASSERT_EQ(second.row.positions.size(), 2u);
  EXPECT_DOUBLE_EQ(second.row.positions[0].x, 201.0);
  EXPECT_DOUBLE_EQ(second.row.positions[1].y, -4.5);
  EXPECT_DOUBLE_EQ(second.row.positions[1].z, 45.0);

  const auto first = ReadTrackIntervalRows(db, "c0ffee", TrackRunsRead::kFirstRunOnly);
  order.clear();
  for (const auto& r : first)
    order.push_back(r.scenario + std::to_string(r.rng_run) + "/" + std::to_string(r.interval));
  EXPECT_EQ(order, (std::vector<std::string>{"z2/0", "z2/1", "a1/0", "a1/1"}));
}

TEST(TrackIntervals, EachIntervalAveragedOverTheRunsOfItsScenarioAndPositioner) {
  testing::TempDir dir;
  Database db(dir.File("store.db"), false, 1000);
  AddThreeRuns(db);
  const auto series = ReadTrackSeriesRows(db, "c0ffee");
  std::vector<std::string> order;
  for (const auto& r : series)
    order.push_back(r.scenario + "/" + std::to_string(r.interval) + "x" + std::to_string(r.runs));
  EXPECT_EQ(order, (std::vector<std::string>{"z/0x2", "z/1x2", "a/0x1", "a/1x1"}));
  ASSERT_EQ(series.size(), 4u);
  EXPECT_EQ(series[0].label, "oracle-track");
  EXPECT_DOUBLE_EQ(series[0].time_s, 1.0);
  EXPECT_NEAR(series[0].reward, 0.525, 1e-12) << "runs 2 and 3";
  EXPECT_NEAR(series[3].reward, 0.61, 1e-12) << "run 1 alone";
  EXPECT_DOUBLE_EQ(series[1].throughput_mbps, 20.0);
  EXPECT_FALSE(series[0].delay_ms.has_value());
  EXPECT_EQ(series[1].delay_ms, std::optional<double>(3.5));
  EXPECT_TRUE(series[1].scored);
  EXPECT_DOUBLE_EQ(series[1].los_share, 0.75);
  EXPECT_DOUBLE_EQ(series[1].demands_met_share, 0.5);
}

}  // namespace
}  // namespace rlpos
