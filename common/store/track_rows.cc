#include "common/store/track_rows.h"

#include <cmath>
#include <limits>
#include <optional>

#include "common/store/run_key_columns.h"
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

// The values of an interval, of one run (v_track_intervals) or averaged over the runs (the
// series), read alike.
struct IntervalValueColumns {
  ResultColumn time_s, scored, reward, throughput_mbps, delay_ms, los_share, demands_met_share;

  // Row: TrackIntervalRow or TrackSeriesRow.
  template <typename Row>
  void Read(const Statement& select, Row& row) const {
    row.time_s = select.Double(time_s);
    row.scored = select.Int(scored) != 0;
    row.reward = select.Double(reward);
    row.throughput_mbps = select.Double(throughput_mbps);
    row.delay_ms = select.OptionalDouble(delay_ms);
    row.los_share = select.Double(los_share);
    row.demands_met_share = select.Double(demands_met_share);
  }
};

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
  const RunKeyColumns run_key(select);
  const ResultColumn fidelity = select.Column("fidelity"), duration_s = select.Column("duration_s"),
                     decision_interval_s = select.Column("decision_interval_s"),
                     intervals = select.Column("intervals"),
                     scored_intervals = select.Column("scored_intervals");
  std::vector<ResultColumn> metrics;
  for (const TrackMetricDef& m : kTrackMetrics)
    metrics.push_back(select.Column(m.key));
  std::vector<TrackRunRow> out;
  while (select.Step()) {
    TrackRunRow row;
    run_key.Read(select, row);
    row.fidelity = select.Text(fidelity);
    row.duration_s = select.Double(duration_s);
    row.decision_interval_s = select.Double(decision_interval_s);
    row.intervals = static_cast<int>(select.Int(intervals));
    row.scored_intervals = static_cast<int>(select.Int(scored_intervals));
    for (std::size_t i = 0; i < kTrackMetrics.size(); ++i) {
      const std::optional<double> v = select.OptionalDouble(metrics[i]);
      row.metrics.*(kTrackMetrics[i].field) = v ? *v : std::numeric_limits<double>::quiet_NaN();
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
  const ResultColumn scenario = select.Column("scenario"), label = select.Column("positioner"),
                     rng_run = select.Column("rng_run"), interval = select.Column("interval");
  const IntervalValueColumns values{
      select.Column("time_s"),           select.Column("scored"),   select.Column("reward"),
      select.Column("throughput_mbps"),  select.Column("delay_ms"), select.Column("los_share"),
      select.Column("demands_met_share")};
  const ResultColumn positions_json = select.Column("positions_json");
  std::vector<TrackIntervalRecord> out;
  while (select.Step()) {
    TrackIntervalRecord record;
    record.scenario = select.Text(scenario);
    record.label = select.Text(label);
    record.rng_run = select.Int(rng_run);
    record.interval = static_cast<int>(select.Int(interval));
    TrackIntervalRow& row = record.row;
    values.Read(select, row);
    // Written by InsertTrackRun from a checked result: [[x, y, z], ...].
    for (const auto& p : nlohmann::json::parse(select.Text(positions_json)))
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
      "SELECT v.scenario, v.positioner, v.interval, COUNT(*) AS runs, "
      "AVG(v.time_s) AS mean_time_s, MIN(v.scored) AS all_scored, AVG(v.reward) AS mean_reward, "
      "AVG(v.throughput_mbps) AS mean_throughput_mbps, AVG(v.delay_ms) AS mean_delay_ms, "
      "AVG(v.los_share) AS mean_los_share, AVG(v.demands_met_share) AS mean_demands_met_share "
      "FROM v_track_intervals" +
      order);
  select.Bind(campaign_id);
  const ResultColumn scenario = select.Column("scenario"), label = select.Column("positioner"),
                     interval = select.Column("interval"), runs = select.Column("runs");
  const IntervalValueColumns values{
      select.Column("mean_time_s"),           select.Column("all_scored"),
      select.Column("mean_reward"),           select.Column("mean_throughput_mbps"),
      select.Column("mean_delay_ms"),         select.Column("mean_los_share"),
      select.Column("mean_demands_met_share")};
  std::vector<TrackSeriesRow> out;
  while (select.Step()) {
    TrackSeriesRow row;
    row.scenario = select.Text(scenario);
    row.label = select.Text(label);
    row.interval = static_cast<int>(select.Int(interval));
    row.runs = static_cast<int>(select.Int(runs));
    values.Read(select, row);
    out.push_back(std::move(row));
  }
  return out;
}

}  // namespace rlpos
