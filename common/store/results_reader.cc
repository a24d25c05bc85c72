#include "common/store/results_reader.h"

#include "common/provenance/provenance.h"
#include "common/store/job_rows.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

CampaignProgress ReadProgress(const Statement& row) {
  CampaignProgress p;
  p.campaign_id = row.Text(0);
  p.name = row.Text(1);
  p.state = row.Text(2);
  p.total = static_cast<int>(row.Int(3));
  p.pending = static_cast<int>(row.Int(4));
  p.ready = static_cast<int>(row.Int(5));
  p.running = static_cast<int>(row.Int(6));
  p.succeeded = static_cast<int>(row.Int(7));
  p.failed = static_cast<int>(row.Int(8));
  p.cancelled = static_cast<int>(row.Int(9));
  p.cached = static_cast<int>(row.Int(10));
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
  std::vector<std::string> builds;
  while (select.Step()) {
    Provenance p;
    p.rlpos_version = select.Text(0);
    p.ns3_version = select.OptionalText(1).value_or("?");
    p.torch_version = select.OptionalText(2).value_or("?");
    p.cyclonedds_version = select.OptionalText(3).value_or("?");
    builds.push_back(DescribeBuild(p));
  }
  return builds;
}

CampaignProgress ResultsReader::Progress(const std::string& campaign_id) {
  Statement select = db_->Prepare(std::string(kProgressColumns) + " WHERE campaign_id = ?");
  select.Bind(campaign_id);
  if (!select.Step())
    throw StoreError(store_.file(), "no campaign \"" + campaign_id + "\"");
  return ReadProgress(select);
}

std::vector<CampaignProgress> ResultsReader::AllProgress() {
  Statement select =
      db_->Prepare(std::string(kProgressColumns) + " ORDER BY created_utc, campaign_id");
  std::vector<CampaignProgress> out;
  while (select.Step())
    out.push_back(ReadProgress(select));
  return out;
}

std::optional<JobRecord> ResultsReader::GetJob(const std::string& job_id) {
  Statement select = db_->Prepare(
      std::string("SELECT id, campaign_id, key, label, state, depends_on, attempt, max_attempts, "
                  "timeout_s, worker_id, error, result_json, COALESCE(slot, 0), ") +
      kParamColumns + " FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return std::nullopt;
  JobRecord r;
  r.id = select.Text(0);
  r.campaign_id = select.Text(1);
  r.key = select.Text(2);
  r.label = select.Text(3);
  r.state = select.Text(4);
  r.depends_on = select.OptionalText(5).value_or("");
  r.attempt = static_cast<int>(select.Int(6));
  r.max_attempts = static_cast<int>(select.Int(7));
  r.timeout_s = select.Double(8);
  r.worker_id = select.OptionalText(9);
  r.error = select.OptionalText(10);
  if (const auto result = select.OptionalText(11))
    r.result = json::parse(*result);
  r.slot = static_cast<int>(select.Int(12));
  r.params = ReadParams(select, 13, r.placement, store_.file());
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
