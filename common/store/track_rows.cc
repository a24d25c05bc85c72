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

std::vector<TrackIntervalRecord> ReadTrackIntervalRows(Database& db, const std::string& campaign_id,
                                                       TrackRunsRead which) {
  const std::string first_run_only =
      which == TrackRunsRead::kFirstRunOnly
          ? " AND v.rng_run = (SELECT MIN(f.rng_run) FROM track_runs f WHERE f.campaign_id = ?1 "
            "AND f.scenario = v.scenario AND f.label = v.positioner)"
          : "";
  // OfCampaignInOrder's filter, narrowed to the first run when asked, then by interval.
  std::string order = OfCampaignInOrder();
  const std::string where = "WHERE v.campaign_id = ?1";
  order.insert(order.find(where) + where.size(), first_run_only);
  Statement select = db.Prepare(
      "SELECT scenario, positioner, rng_run, interval, time_s, scored, reward, throughput_mbps, "
      "delay_ms, los_share, demands_met_share, positions_json FROM v_track_intervals" +
      order + ", interval");
  select.Bind(campaign_id);
  std::vector<TrackIntervalRecord> out;
  while (select.Step()) {
    TrackIntervalRecord record;
    record.scenario = select.Text(0);
    record.label = select.Text(1);
    record.rng_run = select.Int(2);
    record.interval = static_cast<int>(select.Int(3));
    TrackIntervalRow& row = record.row;
    row.time_s = select.Double(4);
    row.scored = select.Int(5) != 0;
    row.reward = select.Double(6);
    row.throughput_mbps = select.Double(7);
    row.delay_ms = select.OptionalDouble(8);
    row.los_share = select.Double(9);
    row.demands_met_share = select.Double(10);
    // Written by InsertTrackRun from a checked result: [[x, y, z], ...].
    for (const auto& p : nlohmann::json::parse(select.Text(11)))
      row.positions.push_back(
          {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()});
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<TrackSeriesRow> ReadTrackSeriesRows(Database& db, const std::string& campaign_id) {
  // OfCampaignInOrder orders by rng_run last, which a grouped query no longer has.
  std::string order = OfCampaignInOrder();
  order.replace(order.find(", rng_run"), std::string(", rng_run").size(), ", interval");
  const std::string group = " ORDER BY";
  order.insert(order.find(group), " GROUP BY v.scenario, v.positioner, v.interval");
  Statement select = db.Prepare(
      "SELECT v.scenario, v.positioner, v.interval, COUNT(*), AVG(v.time_s), MIN(v.scored), "
      "AVG(v.reward), AVG(v.throughput_mbps), AVG(v.delay_ms), AVG(v.los_share), "
      "AVG(v.demands_met_share) FROM v_track_intervals" +
      order);
  select.Bind(campaign_id);
  std::vector<TrackSeriesRow> out;
  while (select.Step()) {
    TrackSeriesRow row;
    row.scenario = select.Text(0);
    row.label = select.Text(1);
    row.interval = static_cast<int>(select.Int(2));
    row.runs = static_cast<int>(select.Int(3));
    row.time_s = select.Double(4);
    row.scored = select.Int(5) != 0;
    row.reward = select.Double(6);
    row.throughput_mbps = select.Double(7);
    row.delay_ms = select.OptionalDouble(8);
    row.los_share = select.Double(9);
    row.demands_met_share = select.Double(10);
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
