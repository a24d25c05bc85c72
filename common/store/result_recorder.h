#pragma once
// Result recording: a running job's successful attempt, checked and written with its
// provenance, metrics (eval and track jobs) and artifacts, in one transaction with what it sets
// off: the dependants' placements (a DependantRule), the identical jobs that waited for it (the
// result cache) and its campaign's state (the ledger).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/campaign/expansion.h"
#include "common/provenance/provenance.h"
#include "common/store/job_result.h"
#include "common/store/store_records.h"
#include "common/store/track_result.h"
#include "common/wire/artifacts.h"

namespace rlpos {

class Database;
class DependantRule;
class JobLedger;
class ResultCache;
class StoreDb;
class Transaction;

class ResultRecorder {
 public:
  ResultRecorder(StoreDb& store, JobLedger& ledger, ResultCache& cache, DependantRule& dependants);

  // A result of train/position jobs must hold a placement (store/job_result.h); of eval jobs,
  // the metrics of rlpos::ToJson(RunMetrics), at the job's placement. A malformed result counts
  // as a failed attempt.
  // `worker_id` non-empty: only the worker that holds the attempt may settle it (else kStale).
  // `provenance` (when given) is kept on the row: host, build versions, scenario sha256.
  // `artifacts` (checked by the caller: wire/artifacts.h) are written under ArtifactsDirOf(file)
  // and listed in the artifacts table; a failure to write them fails the attempt.
  JobUpdate RecordSuccess(const std::string& job_id, int attempt, const nlohmann::json& result,
                          const std::string& worker_id = "", const Provenance* provenance = nullptr,
                          const std::vector<ArtifactFile>& artifacts = {});

 private:
  // The job's row as RecordSuccess reads it before writing.
  struct SettlingJob {
    int max_attempts = 1;
    std::string campaign_id, label, scenario;
    JobKind kind = JobKind::kEval;
    std::optional<std::int64_t> rng_run;
    std::optional<Placement> placement;
    std::string positioner, fidelity;  // position and track jobs; train and track jobs
    std::optional<double> duration_s;
  };
  // A result as its job's kind reads it.
  struct CheckedResult {
    EvalResult eval;       // eval jobs
    TrackRunResult track;  // track jobs
    Placement produced;    // train and position jobs
  };
  // kUnknown or kStale when the attempt is not the job's running one; else fills `job`.
  std::optional<JobUpdate> ReadSettling(const std::string& job_id, int attempt,
                                        const std::string& worker_id, SettlingJob& job);
  // Throws std::invalid_argument for a result the job refuses; fills `checked`.
  void CheckResult(const std::string& job_id, const SettlingJob& job, const nlohmann::json& result,
                   CheckedResult& checked);
  // The attempt fails instead of succeeding; commits.
  JobUpdate FailSettling(const std::string& job_id, int attempt, const SettlingJob& job,
                         const std::string& error, Transaction& transaction);
  // Writes the files beside the database and lists them. Throws (files or rows).
  void StoreArtifacts(const std::string& job_id, const std::vector<ArtifactFile>& artifacts);
  // One statement for the row: the result and, when given, where it came from.
  void MarkSucceeded(const std::string& job_id, int attempt, const nlohmann::json& result,
                     const Provenance* provenance);

  StoreDb& store_;
  Database* db_;
  JobLedger& ledger_;
  ResultCache& cache_;
  DependantRule& dependants_;
};

}  // namespace rlpos
