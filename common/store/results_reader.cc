#include "common/store/results_reader.h"

#include "common/provenance/provenance.h"
#include "common/store/job_rows.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

// The columns of kProgressColumns, and the counts' members they fill.
struct ProgressColumns {
  explicit ProgressColumns(const Statement& select)
      : campaign_id(select.Column("campaign_id")),
        name(select.Column("name")),
        state(select.Column("state")) {
    for (const auto& [column, member] : kCounts)
      counts.push_back({select.Column(column), member});
  }
  static constexpr std::pair<const char*, int CampaignProgress::*> kCounts[] = {
      {"total", &CampaignProgress::total},         {"pending", &CampaignProgress::pending},
      {"ready", &CampaignProgress::ready},         {"running", &CampaignProgress::running},
      {"succeeded", &CampaignProgress::succeeded}, {"failed", &CampaignProgress::failed},
      {"cancelled", &CampaignProgress::cancelled}, {"cached", &CampaignProgress::cached}};
  ResultColumn campaign_id, name, state;
  std::vector<std::pair<ResultColumn, int CampaignProgress::*>> counts;
};

CampaignProgress ReadProgress(const Statement& row, const ProgressColumns& c) {
  CampaignProgress p;
  p.campaign_id = row.Text(c.campaign_id);
  p.name = row.Text(c.name);
  p.state = row.Text(c.state);
  for (const auto& [column, member] : c.counts)
    p.*member = static_cast<int>(row.Int(column));
  return p;
}

constexpr const char* kProgressColumns =
    "SELECT campaign_id, name, state, total, pending, ready, running, succeeded, failed, "
    "cancelled, cached FROM v_campaign_progress";

}  // namespace

ResultsReader::ResultsReader(StoreDb& store) : store_(store), db_(&store.sql()) {}

const std::string& ResultsReader::file() const {
  return store_.file();
}

std::vector<std::string> ResultsReader::CampaignBuilds(const std::string& campaign_id) {
  Statement select = db_->Prepare(
      "SELECT DISTINCT rlpos_version, ns3_version, torch_version, cyclonedds_version FROM jobs "
      "WHERE campaign_id = ? AND state = 'succeeded' AND rlpos_version IS NOT NULL "
      "ORDER BY 1, 2, 3, 4");
  select.Bind(campaign_id);
  const ResultColumn rlpos = select.Column("rlpos_version"), ns3 = select.Column("ns3_version"),
                     torch = select.Column("torch_version"),
                     cyclonedds = select.Column("cyclonedds_version");
  std::vector<std::string> builds;
  while (select.Step()) {
    Provenance p;
    p.rlpos_version = select.Text(rlpos);
    p.ns3_version = select.OptionalText(ns3).value_or("?");
    p.torch_version = select.OptionalText(torch).value_or("?");
    p.cyclonedds_version = select.OptionalText(cyclonedds).value_or("?");
    builds.push_back(DescribeBuild(p));
  }
  return builds;
}

CampaignProgress ResultsReader::Progress(const std::string& campaign_id) {
  Statement select = db_->Prepare(std::string(kProgressColumns) + " WHERE campaign_id = ?");
  select.Bind(campaign_id);
  if (!select.Step())
    throw StoreError(store_.file(), "no campaign \"" + campaign_id + "\"");
  return ReadProgress(select, ProgressColumns(select));
}

std::vector<CampaignProgress> ResultsReader::AllProgress() {
  Statement select =
      db_->Prepare(std::string(kProgressColumns) + " ORDER BY created_utc, campaign_id");
  const ProgressColumns columns(select);
  std::vector<CampaignProgress> out;
  while (select.Step())
    out.push_back(ReadProgress(select, columns));
  return out;
}

std::optional<JobRecord> ResultsReader::GetJob(const std::string& job_id) {
  Statement select = db_->Prepare(
      std::string("SELECT id, campaign_id, key, label, state, depends_on, attempt, max_attempts, "
                  "timeout_s, worker_id, error, result_json, COALESCE(slot, 0) AS slot, ") +
      kParamColumns + " FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return std::nullopt;
  const auto column = [&select](const char* name) { return select.Column(name); };
  JobRecord r;
  r.id = select.Text(column("id"));
  r.campaign_id = select.Text(column("campaign_id"));
  r.key = select.Text(column("key"));
  r.label = select.Text(column("label"));
  r.state = select.Text(column("state"));
  r.depends_on = select.OptionalText(column("depends_on")).value_or("");
  r.attempt = static_cast<int>(select.Int(column("attempt")));
  r.max_attempts = static_cast<int>(select.Int(column("max_attempts")));
  r.timeout_s = select.Double(column("timeout_s"));
  r.worker_id = select.OptionalText(column("worker_id"));
  r.error = select.OptionalText(column("error"));
  if (const auto result = select.OptionalText(column("result_json")))
    r.result = json::parse(*result);
  r.slot = static_cast<int>(select.Int(column("slot")));
  r.params = ReadParams(select, ParamColumns(select), r.placement, store_.file());
  return r;
}

std::vector<MetricRow> ResultsReader::Metrics(const std::string& campaign_id) {
  return ReadMetricRows(*db_, campaign_id);
}

std::vector<UavMetricRow> ResultsReader::UavMetrics(const std::string& campaign_id) {
  return ReadUavMetricRows(*db_, campaign_id);
}

std::vector<TrackRunRow> ResultsReader::TrackRuns(const std::string& campaign_id) {
  return ReadTrackRunRows(*db_, campaign_id);
}

std::vector<TrackIntervalRecord> ResultsReader::TrackIntervals(const std::string& campaign_id,
                                                               TrackRunsRead which) {
  return ReadTrackIntervalRows(*db_, campaign_id, which);
}

std::vector<TrackSeriesRow> ResultsReader::TrackSeries(const std::string& campaign_id) {
  return ReadTrackSeriesRows(*db_, campaign_id);
}

std::vector<OptimalityRow> ResultsReader::Optimality(const std::string& campaign_id) {
  return ReadOptimalityRows(*db_, campaign_id);
}

}  // namespace rlpos
