#include "common/store/result_recorder.h"

#include <algorithm>
#include <stdexcept>

#include "common/store/artifact_files.h"
#include "common/store/dependant_rule.h"
#include "common/store/job_ledger.h"
#include "common/store/job_result.h"
#include "common/store/job_rows.h"
#include "common/store/metric_rows.h"
#include "common/store/result_cache.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"
#include "common/store/track_rows.h"

namespace rlpos {
namespace {

using nlohmann::json;

bool SamePlacement(const Placement& a, const Placement& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), SamePosition);
}

}  // namespace

ResultRecorder::ResultRecorder(StoreDb& store, JobLedger& ledger, ResultCache& cache,
                               DependantRule& dependants)
    : store_(store), db_(&store.sql()), ledger_(ledger), cache_(cache), dependants_(dependants) {}

JobUpdate ResultRecorder::RecordSuccess(const std::string& job_id, int attempt, const json& result,
                                        const std::string& worker_id, const Provenance* provenance,
                                        const std::vector<ArtifactFile>& artifacts) {
  Transaction transaction(*db_);
  SettlingJob job;
  if (const auto ignored = ReadSettling(job_id, attempt, worker_id, job))
    return *ignored;
  // Check the result before anything is written: a malformed one is a failed attempt.
  CheckedResult checked;
  try {
    CheckResult(job_id, job, result, checked);
  } catch (const std::invalid_argument& e) {
    return FailSettling(job_id, attempt, job, std::string("malformed result: ") + e.what(),
                        transaction);
  }
  if (!artifacts.empty()) {
    try {
      StoreArtifacts(job_id, artifacts);
    } catch (const std::exception& e) {
      return FailSettling(job_id, attempt, job,
                          std::string("cannot store its artifacts: ") + e.what(), transaction);
    }
  }
  MarkSucceeded(job_id, attempt, result, provenance);
  const EvalRowKey key{job_id, job.campaign_id, job.scenario, job.label, job.rng_run.value_or(0)};
  if (job.kind == JobKind::kEval) {
    InsertEvalMetrics(*db_, key, checked.eval);
  } else if (job.kind == JobKind::kTrack) {
    InsertTrackRun(*db_, key, checked.track);
  } else {
    dependants_.Bind(job_id, checked.produced);
  }
  cache_.ServeWaiting(job_id);
  ledger_.UpdateCampaignState(job.campaign_id);
  transaction.Commit();
  return JobUpdate::kSucceeded;
}

std::optional<JobUpdate> ResultRecorder::ReadSettling(const std::string& job_id, int attempt,
                                                      const std::string& worker_id,
                                                      SettlingJob& job) {
  Statement select = db_->Prepare(
      "SELECT state, attempt, max_attempts, campaign_id, label, worker_id, kind, scenario, "
      "rng_run, x, y, z, positions_json, positioner, fidelity, duration_s FROM jobs WHERE id = ?");
  select.Bind(job_id);
  if (!select.Step())
    return JobUpdate::kUnknown;
  const auto column = [&select](const char* name) { return select.Column(name); };
  if (select.Text(column("state")) != "running" || select.Int(column("attempt")) != attempt)
    return JobUpdate::kStale;
  if (!worker_id.empty() && select.OptionalText(column("worker_id")) != worker_id)
    return JobUpdate::kStale;
  job.max_attempts = static_cast<int>(select.Int(column("max_attempts")));
  job.campaign_id = select.Text(column("campaign_id"));
  job.label = select.Text(column("label"));
  job.kind = ParseJobKind(select.Text(column("kind")));
  job.scenario = select.Text(column("scenario"));
  job.rng_run = select.OptionalInt(column("rng_run"));
  job.positioner = select.OptionalText(column("positioner")).value_or("");
  job.fidelity = select.OptionalText(column("fidelity")).value_or("");
  job.duration_s = select.OptionalDouble(column("duration_s"));
  try {
    job.placement = ReadPlacement(select, PlacementColumns(select));
  } catch (const std::exception& e) {
    throw StoreError(store_.file(), "job " + job_id + ": malformed positions_json: " + e.what());
  }
  select.Reset();  // done reading: the row is about to change
  return std::nullopt;
}

void ResultRecorder::CheckResult(const std::string& job_id, const SettlingJob& job,
                                 const json& result, CheckedResult& checked) {
  EvalResult& eval = checked.eval;
  if (job.kind == JobKind::kTrack) {
    checked.track = ParseTrackResult(result);
    const TrackRunResult& t = checked.track;
    if (!job.rng_run || static_cast<std::int64_t>(t.run) != *job.rng_run ||
        t.positioner != job.positioner || t.fidelity != job.fidelity || !job.duration_s ||
        t.duration_s != *job.duration_s) {
      throw std::invalid_argument(
          "result is of another run, positioner, fidelity or duration "
          "than the job's");
    }
  } else if (job.kind == JobKind::kEval) {
    eval = ParseEvalResult(result);
    if (eval.run && job.rng_run && static_cast<std::int64_t>(*eval.run) != *job.rng_run) {
      throw std::invalid_argument("result is of RngRun " + std::to_string(*eval.run) +
                                  ", the job's is " + std::to_string(*job.rng_run));
    }
    if (job.placement && !SamePlacement(*job.placement, eval.placement))
      throw std::invalid_argument("result is of another placement than the job's");
  } else {
    checked.produced = ProducedPlacement(result);
    dependants_.Check(job_id, checked.produced);
  }
}

JobUpdate ResultRecorder::FailSettling(const std::string& job_id, int attempt,
                                       const SettlingJob& job, const std::string& error,
                                       Transaction& transaction) {
  const JobUpdate update = ledger_.FailAttempt(job_id, attempt, job.max_attempts, error);
  ledger_.UpdateCampaignState(job.campaign_id);
  transaction.Commit();
  return update;
}

void ResultRecorder::StoreArtifacts(const std::string& job_id,
                                    const std::vector<ArtifactFile>& artifacts) {
  // The files first, then the rows that list them: a row never names a missing file. A file
  // written for a commit that then fails is overwritten by the job's next success.
  Transaction rows(*db_);  // none of them if one file fails
  const std::string root = ArtifactsDirOf(store_.file());
  Statement insert = db_->Prepare(
      "INSERT OR REPLACE INTO artifacts (job_id, name, path, sha256, bytes) VALUES (?, ?, ?, ?, "
      "?)");
  for (const auto& a : artifacts) {
    const std::string path = ArtifactRelativePath(job_id, a.name);
    WriteArtifactFile(root, path, a.data);
    insert.Reset();
    insert.Bind(job_id)
        .Bind(a.name)
        .Bind(path)
        .Bind(a.sha256)
        .Bind(static_cast<std::int64_t>(a.data.size()))
        .Run();
  }
  insert.Reset();
  rows.Commit();
}

void ResultRecorder::MarkSucceeded(const std::string& job_id, int attempt, const json& result,
                                   const Provenance* provenance) {
  const auto text = [](const std::string& v) {
    return v.empty() ? std::nullopt : std::optional<std::string>(v);
  };
  const Provenance none;
  const Provenance& p = provenance ? *provenance : none;
  db_->Prepare(
         "UPDATE jobs SET state = 'succeeded', finished_at = ?, result_json = ?, error = NULL, "
         "host = COALESCE(?, host), rlpos_version = COALESCE(?, rlpos_version), "
         "ns3_version = COALESCE(?, ns3_version), torch_version = COALESCE(?, torch_version), "
         "cyclonedds_version = COALESCE(?, cyclonedds_version), "
         "scenario_sha256 = COALESCE(?, scenario_sha256) "
         "WHERE id = ? AND attempt = ? AND state = 'running'")
      .Bind(store_.Now())
      .Bind(result.dump())
      .Bind(text(p.host))
      .Bind(text(p.rlpos_version))
      .Bind(text(p.ns3_version))
      .Bind(text(p.torch_version))
      .Bind(text(p.cyclonedds_version))
      .Bind(text(p.scenario_sha256))
      .Bind(job_id)
      .Bind(attempt)
      .Run();
}

}  // namespace rlpos
