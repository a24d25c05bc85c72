#include "common/store/track_rows.h"

#include <cmath>
#include <limits>
#include <optional>

#include "common/store/sqlite_db.h"

namespace rlpos {
namespace {

std::string MetricColumns() {
  std::string out;
  for (const TrackMetricDef& m : kTrackMetrics)
    out += std::string(", ") + m.key;
  return out;
}

std::string Placeholders(std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i)
    out += i == 0 ? "?" : ", ?";
  return out;
}

std::string PositionsJson(const Placement& positions) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec3& p : positions)
    out.push_back({p.x, p.y, p.z});
  return out.dump();
}

std::optional<double> Stored(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

}  // namespace

void InsertTrackRun(Database& db, const EvalRowKey& key, const TrackRunResult& run) {
  Statement insert = db.Prepare(
      "INSERT INTO track_runs (job_id, campaign_id, scenario, label, rng_run, fidelity, "
      "duration_s, decision_interval_s, intervals, scored_intervals" +
      MetricColumns() + ") VALUES (" + Placeholders(10 + kTrackMetrics.size()) + ")");
  insert.Bind(key.job_id)
      .Bind(key.campaign_id)
      .Bind(key.scenario)
      .Bind(key.label)
      .Bind(key.rng_run)
      .Bind(run.fidelity)
      .Bind(run.duration_s)
      .Bind(run.decision_interval_s)
      .Bind(static_cast<std::int64_t>(run.intervals.size()))
      .Bind(run.scored_intervals);
  for (const TrackMetricDef& m : kTrackMetrics)
    insert.Bind(Stored(run.metrics.*(m.field)));
  insert.Run();
  Statement interval = db.Prepare(
      "INSERT INTO track_intervals (job_id, interval, campaign_id, scenario, label, rng_run, "
      "time_s, scored, reward, throughput_mbps, delay_ms, los_share, demands_met_share, "
      "positions_json) VALUES (" +
      Placeholders(14) + ")");
  for (std::size_t i = 0; i < run.intervals.size(); ++i) {
    const TrackIntervalRow& row = run.intervals[i];
    interval.Reset();
    interval.Bind(key.job_id)
        .Bind(static_cast<std::int64_t>(i))
        .Bind(key.campaign_id)
        .Bind(key.scenario)
        .Bind(key.label)
        .Bind(key.rng_run)
        .Bind(row.time_s)
        .Bind(row.scored ? 1 : 0)
        .Bind(row.reward)
        .Bind(row.throughput_mbps)
        .Bind(row.delay_ms)
        .Bind(row.los_share)
        .Bind(row.demands_met_share)
        .Bind(PositionsJson(row.positions))
        .Run();
  }
}

std::vector<TrackRunRow> ReadTrackRunRows(Database& db, const std::string& campaign_id) {
  Statement select = db.Prepare(
      "SELECT job_id, scenario, positioner, rng_run, fidelity, duration_s, decision_interval_s, "
      "intervals, scored_intervals" +
      MetricColumns() + " FROM v_track_runs" + OfCampaignInOrder());
  select.Bind(campaign_id);
  std::vector<TrackRunRow> out;
  while (select.Step()) {
    TrackRunRow row;
    row.job_id = select.Text(0);
    row.scenario = select.Text(1);
    row.label = select.Text(2);
    row.rng_run = select.Int(3);
    row.fidelity = select.Text(4);
    row.duration_s = select.Double(5);
    row.decision_interval_s = select.Double(6);
    row.intervals = static_cast<int>(select.Int(7));
    row.scored_intervals = static_cast<int>(select.Int(8));
    int column = 9;
    for (const TrackMetricDef& m : kTrackMetrics) {
      const std::optional<double> v = select.OptionalDouble(column++);
      row.metrics.*(m.field) = v ? *v : std::numeric_limits<double>::quiet_NaN();
    }
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
