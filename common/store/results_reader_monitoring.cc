// What `status` and `run` show while a campaign runs: workers, timings, failed jobs.
#include "common/store/results_reader.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"

namespace rlpos {

std::vector<WorkerRecord> ResultsReader::ListWorkers() {
  Statement select = db_->Prepare(
      "SELECT id, host, pid, slots, busy, state, first_seen, last_seen FROM workers "
      "ORDER BY state = 'alive' DESC, id");
  const ResultColumn id = select.Column("id"), host = select.Column("host"),
                     pid = select.Column("pid"), slots = select.Column("slots"),
                     busy = select.Column("busy"), state = select.Column("state"),
                     first_seen = select.Column("first_seen"),
                     last_seen = select.Column("last_seen");
  std::vector<WorkerRecord> out;
  while (select.Step()) {
    WorkerRecord w;
    w.id = select.Text(id);
    w.host = select.Text(host);
    w.pid = select.Int(pid);
    w.slots = static_cast<int>(select.Int(slots));
    w.busy = static_cast<int>(select.Int(busy));
    w.state = select.Text(state);
    w.first_seen = select.Double(first_seen);
    w.last_seen = select.Double(last_seen);
    out.push_back(std::move(w));
  }
  return out;
}

std::optional<nlohmann::json> ResultsReader::CampaignSpecPart(const std::string& campaign_id,
                                                              const std::string& key) {
  // json_quote keeps an extracted object or array as it is and quotes a string.
  Statement select = db_->Prepare(
      "SELECT json_type(spec_json, ?1) IS NOT NULL AS present, "
      "json_quote(json_extract(spec_json, ?1)) AS part FROM campaigns WHERE id = ?2");
  select.Bind("$.\"" + key + "\"").Bind(campaign_id);
  if (!select.Step())
    return std::nullopt;
  nlohmann::json part = nlohmann::json::object();
  if (select.Int(select.Column("present")) != 0)
    part[key] = nlohmann::json::parse(select.Text(select.Column("part")));
  return part;
}

std::vector<RunningJobView> ResultsReader::RunningJobs(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT key, COALESCE(worker_id, '') AS worker, attempt, COALESCE(started_at, 0) AS since, "
      "COALESCE(progress, '') AS progress_text FROM jobs "
      "WHERE campaign_id = ? AND state = 'running' ORDER BY started_at, seq");
  select.Bind(campaign_id);
  const ResultColumn key = select.Column("key"), worker = select.Column("worker"),
                     attempt = select.Column("attempt"), since = select.Column("since"),
                     progress = select.Column("progress_text");
  std::vector<RunningJobView> out;
  while (select.Step()) {
    out.push_back({select.Text(key), select.Text(worker), static_cast<int>(select.Int(attempt)),
                   select.Double(since), select.Text(progress)});
  }
  return out;
}

CampaignTiming ResultsReader::Timing(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT c.created_at, MIN(j.started_at) AS first_started_at, "
      "MAX(j.finished_at) AS last_finished_at, "
      "COALESCE(SUM(j.state IN ('succeeded', 'failed', 'cancelled')), 0) AS finished "
      "FROM campaigns c LEFT JOIN jobs j ON j.campaign_id = c.id WHERE c.id = ?");
  select.Bind(campaign_id);
  select.Step();
  CampaignTiming t;
  t.created_at = select.Double(select.Column("created_at"));
  t.first_started_at = select.OptionalDouble(select.Column("first_started_at"));
  t.last_finished_at = select.OptionalDouble(select.Column("last_finished_at"));
  t.finished = static_cast<int>(select.Int(select.Column("finished")));
  return t;
}

std::vector<FailedJob> ResultsReader::FailedJobs(const std::string& campaign_id) {
  store_.RequireCampaign(campaign_id);
  Statement select = db_->Prepare(
      "SELECT key, attempt, COALESCE(error, '') AS error_text FROM jobs "
      "WHERE campaign_id = ? AND state = 'failed' ORDER BY seq");
  select.Bind(campaign_id);
  const ResultColumn key = select.Column("key"), attempt = select.Column("attempt"),
                     error = select.Column("error_text");
  std::vector<FailedJob> out;
  while (select.Step()) {
    out.push_back({select.Text(key), static_cast<int>(select.Int(attempt)), select.Text(error)});
  }
  return out;
}

namespace {

constexpr const char* kArtifactColumns =
    "SELECT a.rowid AS artifact_id, a.job_id, j.key, a.name, a.path, "
    "COALESCE(a.sha256, '') AS sha256_text, COALESCE(a.bytes, 0) AS byte_count, j.cached_from, "
    "j.scenario, j.label FROM artifacts a JOIN jobs j ON j.id = a.job_id ";

struct ArtifactColumns {
  explicit ArtifactColumns(const Statement& select)
      : id(select.Column("artifact_id")),
        job_id(select.Column("job_id")),
        key(select.Column("key")),
        name(select.Column("name")),
        path(select.Column("path")),
        sha256(select.Column("sha256_text")),
        bytes(select.Column("byte_count")),
        cached_from(select.Column("cached_from")),
        scenario(select.Column("scenario")),
        label(select.Column("label")) {}
  ResultColumn id, job_id, key, name, path, sha256, bytes, cached_from, scenario, label;
};

ArtifactRecord ReadArtifact(const Statement& row, const ArtifactColumns& c) {
  ArtifactRecord a;
  a.id = row.Int(c.id);
  a.job_id = row.Text(c.job_id);
  a.job_key = row.Text(c.key);
  a.name = row.Text(c.name);
  a.path = row.Text(c.path);
  a.sha256 = row.Text(c.sha256);
  a.bytes = row.Int(c.bytes);
  a.cached_from = row.OptionalText(c.cached_from);
  a.scenario = row.Text(c.scenario);
  a.label = row.Text(c.label);
  return a;
}

}  // namespace

std::vector<ArtifactRecord> ResultsReader::Artifacts(const std::string& campaign_or_job_id) {
  Statement select = db_->Prepare(std::string(kArtifactColumns) +
                                  "WHERE j.campaign_id = ? OR j.id = ? ORDER BY j.seq, a.name");
  select.Bind(campaign_or_job_id).Bind(campaign_or_job_id);
  const ArtifactColumns columns(select);
  std::vector<ArtifactRecord> out;
  while (select.Step())
    out.push_back(ReadArtifact(select, columns));
  return out;
}

std::optional<ArtifactRecord> ResultsReader::Artifact(std::int64_t id) {
  Statement select = db_->Prepare(std::string(kArtifactColumns) + "WHERE a.rowid = ?");
  select.Bind(id);
  if (!select.Step())
    return std::nullopt;
  return ReadArtifact(select, ArtifactColumns(select));
}

}  // namespace rlpos
