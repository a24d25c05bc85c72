#include "common/store/result_cache.h"

#include <nlohmann/json.hpp>

#include "common/provenance/provenance.h"
#include "common/store/result_recorder.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"

namespace rlpos {

ResultCache::ResultCache(StoreDb& store) : store_(store), db_(&store.sql()) {}

void ResultCache::ResolveFromCache(const std::string& job_id) {
  Statement job = db_->Prepare(
      "SELECT j.cache_key, j.attempt, c.use_cache FROM jobs j JOIN campaigns c ON "
      "c.id = j.campaign_id WHERE j.id = ? AND j.state = 'ready'");
  job.Bind(job_id);
  if (!job.Step())
    return;
  const std::optional<std::string> key = job.OptionalText(job.Column("cache_key"));
  const int attempt = static_cast<int>(job.Int(job.Column("attempt")));
  const bool use_cache = job.Int(job.Column("use_cache")) != 0;
  job.Reset();
  if (!key || !use_cache)
    return;
  Statement done = db_->Prepare(
      "SELECT id FROM jobs WHERE cache_key = ? AND state = 'succeeded' AND id != ? "
      "ORDER BY cached_from IS NOT NULL, finished_at LIMIT 1");
  done.Bind(*key).Bind(job_id);
  if (done.Step()) {
    const std::string source = done.Text(done.Column("id"));
    done.Reset();
    ServeFrom(job_id, attempt, source);
    return;
  }
  done.Reset();
  // An identical job that will run (and does not itself wait): wait for its result.
  Statement twin = db_->Prepare(
      "SELECT id FROM jobs WHERE cache_key = ? AND state IN ('ready', 'running') AND id != ? "
      "AND cache_twin IS NULL ORDER BY state = 'ready', seq LIMIT 1");
  twin.Bind(*key).Bind(job_id);
  if (twin.Step()) {
    const std::string other = twin.Text(twin.Column("id"));
    twin.Reset();
    db_->Prepare("UPDATE jobs SET cache_twin = ? WHERE id = ?").Bind(other).Bind(job_id).Run();
  }
}

void ResultCache::ServeWaiting(const std::string& job_id) {
  Statement waiting =
      db_->Prepare("SELECT id, attempt FROM jobs WHERE cache_twin = ? AND state = 'ready'");
  waiting.Bind(job_id);
  std::vector<std::pair<std::string, int>> jobs;
  const ResultColumn id_column = waiting.Column("id"), attempt_column = waiting.Column("attempt");
  while (waiting.Step())
    jobs.emplace_back(waiting.Text(id_column), static_cast<int>(waiting.Int(attempt_column)));
  waiting.Reset();
  for (const auto& [id, attempt] : jobs)
    ServeFrom(id, attempt, job_id);
}

void ResultCache::ServeFrom(const std::string& job_id, int attempt, const std::string& source) {
  Statement select = db_->Prepare(
      "SELECT result_json, host, rlpos_version, ns3_version, torch_version, cyclonedds_version, "
      "scenario_sha256 FROM jobs WHERE id = ? AND state = 'succeeded'");
  select.Bind(source);
  if (!select.Step())
    return;
  nlohmann::json result;
  try {
    result = nlohmann::json::parse(select.Text(select.Column("result_json")));
  } catch (const nlohmann::json::exception& e) {
    throw StoreError(store_.file(), "job " + source + ": malformed result_json: " + e.what());
  }
  Provenance provenance;
  const auto text = [&select](const char* column) {
    return select.OptionalText(select.Column(column)).value_or("");
  };
  provenance.host = text("host");
  provenance.rlpos_version = text("rlpos_version");
  provenance.ns3_version = text("ns3_version");
  provenance.torch_version = text("torch_version");
  provenance.cyclonedds_version = text("cyclonedds_version");
  provenance.scenario_sha256 = text("scenario_sha256");
  select.Reset();

  Transaction transaction(*db_);
  db_->Prepare(
         "UPDATE jobs SET state = 'running', worker_id = NULL, started_at = ?, cache_twin = NULL "
         "WHERE id = ? AND attempt = ? AND state = 'ready'")
      .Bind(store_.Now())
      .Bind(job_id)
      .Bind(attempt)
      .Run();
  if (db_->Changes() != 1)
    return;
  // The same path as a worker's result: metrics for an eval, positions bound for dependants
  // (which may be served in turn).
  // A result this job would refuse (which the same content rules out) is not served: the
  // savepoint rolls back and the job runs itself.
  if (recorder_->RecordSuccess(job_id, attempt, result, "", &provenance) != JobUpdate::kSucceeded)
    return;
  db_->Prepare("UPDATE jobs SET cached_from = ? WHERE id = ?").Bind(source).Bind(job_id).Run();
  db_->Prepare(
         "INSERT OR REPLACE INTO artifacts (job_id, name, path, sha256, bytes) "
         "SELECT ?, name, path, sha256, bytes FROM artifacts WHERE job_id = ?")
      .Bind(job_id)
      .Bind(source)
      .Run();
  transaction.Commit();
}

}  // namespace rlpos
