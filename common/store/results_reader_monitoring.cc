// What `status` and `run` show while a campaign runs: workers, timings, failed jobs.
#include "common/store/results_reader.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"

namespace rlpos {

std::vector<WorkerRecord> ResultsReader::ListWorkers() {
  Statement select = db_->Prepare(
      "SELECT id, host, pid, slots, busy, state, first_seen, last_seen FROM workers "
      "ORDER BY state = 'alive' DESC, id");
  std::vector<WorkerRecord> out;
  while (select.Step()) {
    WorkerRecord w;
    w.id = select.Text(0);
    w.host = select.Text(1);
    w.pid = select.Int(2);
    w.slots = static_cast<int>(select.Int(3));
    w.busy = static_cast<int>(select.Int(4));
    w.state = select.Text(5);
    w.first_seen = select.Double(6);
    w.last_seen = select.Double(7);
    out.push_back(std::move(w));
  }
  return out;
}

std::optional<nlohmann::json> ResultsReader::CampaignSpecPart(const std::string& campaign_id,
                                                              const std::string& key) {
  // json_quote keeps an extracted object or array as it is and quotes a string.
  Statement select = db_->Prepare(
      "SELECT json_type(spec_json, ?1) IS NOT NULL, json_quote(json_extract(spec_json, ?1)) "
      "FROM campaigns WHERE id = ?2");
  select.Bind("$.\"" + key + "\"").Bind(campaign_id);
  if (!select.Step())
    return std::nullopt;
  nlohmann::json part = nlohmann::json::object();
  if (select.Int(0) != 0)
    part[key] = nlohmann::json::parse(select.Text(1));
  return part;
}

std::vector<RunningJobView> ResultsReader::RunningJobs(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT key, COALESCE(worker_id, ''), attempt, COALESCE(started_at, 0), "
      "COALESCE(progress, '') FROM jobs WHERE campaign_id = ? AND state = 'running' "
      "ORDER BY started_at, seq");
  select.Bind(campaign_id);
  std::vector<RunningJobView> out;
  while (select.Step()) {
    out.push_back({select.Text(0), select.Text(1), static_cast<int>(select.Int(2)),
                   select.Double(3), select.Text(4)});
  }
  return out;
}

CampaignTiming ResultsReader::Timing(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT c.created_at, MIN(j.started_at), MAX(j.finished_at), "
      "COALESCE(SUM(j.state IN ('succeeded', 'failed', 'cancelled')), 0) "
      "FROM campaigns c LEFT JOIN jobs j ON j.campaign_id = c.id WHERE c.id = ?");
  select.Bind(campaign_id);
  select.Step();
  CampaignTiming t;
  t.created_at = select.Double(0);
  t.first_started_at = select.OptionalDouble(1);
  t.last_finished_at = select.OptionalDouble(2);
  t.finished = static_cast<int>(select.Int(3));
  return t;
}

std::vector<FailedJob> ResultsReader::FailedJobs(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT key, attempt, COALESCE(error, '') FROM jobs "
      "WHERE campaign_id = ? AND state = 'failed' ORDER BY seq");
  select.Bind(campaign_id);
  std::vector<FailedJob> out;
  while (select.Step()) {
    out.push_back({select.Text(0), static_cast<int>(select.Int(1)), select.Text(2)});
  }
  return out;
}

namespace {

constexpr const char* kArtifactColumns =
    "SELECT a.rowid, a.job_id, j.key, a.name, a.path, COALESCE(a.sha256, ''), "
    "COALESCE(a.bytes, 0), j.cached_from, j.scenario, j.label "
    "FROM artifacts a JOIN jobs j ON j.id = a.job_id ";

ArtifactRecord ReadArtifact(const Statement& row) {
  ArtifactRecord a;
  a.id = row.Int(0);
  a.job_id = row.Text(1);
  a.job_key = row.Text(2);
  a.name = row.Text(3);
  a.path = row.Text(4);
  a.sha256 = row.Text(5);
  a.bytes = row.Int(6);
  a.cached_from = row.OptionalText(7);
  a.scenario = row.Text(8);
  a.label = row.Text(9);
  return a;
}

}  // namespace

std::vector<ArtifactRecord> ResultsReader::Artifacts(const std::string& campaign_or_job_id) {
  Statement select = db_->Prepare(std::string(kArtifactColumns) +
                                  "WHERE j.campaign_id = ? OR j.id = ? ORDER BY j.seq, a.name");
  select.Bind(campaign_or_job_id).Bind(campaign_or_job_id);
  std::vector<ArtifactRecord> out;
  while (select.Step())
    out.push_back(ReadArtifact(select));
  return out;
}

std::optional<ArtifactRecord> ResultsReader::Artifact(std::int64_t id) {
  Statement select = db_->Prepare(std::string(kArtifactColumns) + "WHERE a.rowid = ?");
  select.Bind(id);
  if (!select.Step())
    return std::nullopt;
  return ReadArtifact(select);
}

}  // namespace rlpos
