#pragma once
// The results store: one SQLite file (WAL mode, one writer: the coordinator) that is the source
// of truth of campaigns, jobs and their results. Every operation is one transaction.
//
// Job states:  pending   waiting for its dependency to succeed
//              ready     runnable (no dependency, or it succeeded); a failed attempt with
//                        attempts left comes back here with attempt + 1
//              running   assigned to a worker for one attempt
//              succeeded / failed / cancelled   final until RetryFailed
// Exactly-once: a result counts only for the job's current attempt while it is running, and a
// succeeded job is final, so a late, duplicate or stale result never changes anything.
// One ResultsStore per thread (the connection is opened without SQLite's mutex); other processes
// may read the file at any time, and write it too, serialized by SQLite's locks.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "campaign/expansion.h"
#include "provenance/provenance.h"
#include "store/metric_rows.h"
#include "wire/artifacts.h"

namespace rlpos {

class Database;
class Transaction;

// Groups a ResultsStore's writes into one SQLite transaction until Commit (rolled back if it
// goes out of scope first): one disk write for a whole scheduling round instead of one per job.
class StoreBatch {
 public:
  explicit StoreBatch(std::unique_ptr<Transaction> transaction);
  ~StoreBatch();
  StoreBatch(StoreBatch&&) noexcept;
  void Commit();

 private:
  std::unique_ptr<Transaction> transaction_;
};

struct StoreOptions {
  bool read_only = false;  // for readers (status, results, report): never writes, never migrates
  int busy_timeout_ms = 5000;
  std::function<double()> clock;  // seconds since the Unix epoch; default: the system clock
  // A job lost with its worker goes back to the queue without using its retries, up to this
  // many times; one more loss fails it.
  int max_infra_losses = 10;
};

struct SubmitResult {
  std::string campaign_id;
  bool created = false;  // false: the same campaign was already there (nothing changed)
  int jobs = 0;          // jobs of the campaign
};

struct ReadyJob {
  std::string id;
  std::string campaign_id;
  std::string key;
  int attempt = 1;
  double timeout_s = 0;
  JobParams params;
  std::optional<Placement> placement;  // eval jobs: bound when their dependency succeeded
};

struct RunningJob {
  std::string id;
  std::string campaign_id;
  std::string worker_id;
  int slot = 0;  // which of the worker's slots runs it
  int attempt = 1;
  double started_at = 0;
  double timeout_s = 0;
};

struct JobRecord {
  std::string id, campaign_id, key, label, state, depends_on;
  int attempt = 1, max_attempts = 1;
  double timeout_s = 0;
  std::optional<std::string> worker_id, error;
  int slot = 0;  // while running: which of the worker's slots
  JobParams params;
  std::optional<Placement> placement;  // eval jobs, once bound: one position per UAV
  std::optional<nlohmann::json> result;
};

// What a RecordSuccess / RecordFailure did.
enum class JobUpdate {
  kSucceeded,  // result recorded (and metrics, for an eval job)
  kRetrying,   // attempt failed; the job is ready again with attempt + 1
  kFailed,     // attempt failed and none is left; dependents fail with it
  kStale,      // ignored: not the job's current running attempt (late, duplicate, cancelled)
  kUnknown,    // ignored: no such job
};
const char* ToString(JobUpdate update);

struct CampaignProgress {
  std::string campaign_id, name, state;  // state: active | cancelled | finished
  int total = 0, pending = 0, ready = 0, running = 0, succeeded = 0, failed = 0, cancelled = 0;
  int cached = 0;  // of the succeeded: served from the result cache
};

// A worker as the coordinator last saw it (DDS liveliness decides alive/lost).
struct WorkerRecord {
  std::string id, host;
  std::int64_t pid = 0;
  int slots = 1, busy = 0;
  std::string state = "alive";  // alive | lost | stopped
  double first_seen = 0, last_seen = 0;
};

// A running job as `status` shows it.
struct RunningJobView {
  std::string key, worker_id;
  int attempt = 1;
  double started_at = 0;
  std::string progress;  // the child's latest progress line ("" if none yet)
};

struct CampaignTiming {
  double created_at = 0;
  std::optional<double> first_started_at, last_finished_at;
  int finished = 0;  // succeeded, failed or cancelled
};

// A row of the artifacts table; `path` is relative to ArtifactsDirOf(the database).
struct ArtifactRecord {
  std::string job_id, job_key, scenario, label, name, path, sha256;
  std::int64_t bytes = 0;
  std::optional<std::string> cached_from;  // the job was served from this one's result
};

struct FailedJob {
  std::string key;
  int attempts = 0;
  std::string error;
};

class ResultsStore {
 public:
  // Opens or creates the file and migrates it to the newest schema. Throws StoreError naming
  // the file (bad path, read-only file, not a database, corrupt, newer schema).
  explicit ResultsStore(const std::string& file, StoreOptions options = {});
  ~ResultsStore();
  ResultsStore(const ResultsStore&) = delete;
  ResultsStore& operator=(const ResultsStore&) = delete;

  const std::string& file() const;
  int SchemaVersion();
  // The distinct builds (DescribeBuild) of a campaign's succeeded jobs that recorded one: more
  // than one means its results come from mixed versions.
  std::vector<std::string> CampaignBuilds(const std::string& campaign_id);
  // Every write until the batch's Commit goes to disk as one transaction.
  StoreBatch Batch();

  // Inserts the campaign and its jobs; re-submitting the same campaign is a no-op.
  SubmitResult Submit(const CampaignPlan& campaign);

  // Ready jobs of active campaigns: oldest campaign first, then expansion order; at most
  // `per_campaign` of each (0 = all).
  std::vector<ReadyJob> ListReady(std::size_t per_campaign = 0);
  // ready -> running for this attempt; false if the job is not ready at that attempt.
  bool MarkRunning(const std::string& job_id, const std::string& worker_id, int slot, int attempt);
  // A result of train/position jobs must hold a placement (store/job_result.h); of eval jobs,
  // the metrics of rlpos::ToJson(RunMetrics), at the job's placement. A malformed result counts as a failed attempt.
  // `worker_id` non-empty: only the worker that holds the attempt may settle it (else kStale).
  // `provenance` (when given) is kept on the row: host, build versions, scenario sha256.
  // `artifacts` (checked by the caller: wire/artifacts.h) are written under ArtifactsDirOf(file())
  // and listed in the artifacts table; a failure to write them fails the attempt.
  JobUpdate RecordSuccess(const std::string& job_id, int attempt, const nlohmann::json& result,
                          const std::string& worker_id = "", const Provenance* provenance = nullptr,
                          const std::vector<ArtifactFile>& artifacts = {});
  JobUpdate RecordFailure(const std::string& job_id, int attempt, const std::string& error,
                          const std::string& worker_id = "");
  // The worker is gone: each of its running jobs fails that attempt ("worker W was lost") and
  // goes back to ready while attempts remain. Returns the ids of the jobs it held.
  std::vector<std::string> RequeueWorker(const std::string& worker_id);
  std::vector<RunningJob> ListRunning();
  // Where the running jobs run: worker, campaign and slot of each (cheaper than ListRunning
  // each round).
  struct RunningSlot {
    std::string worker_id, campaign_id;
    int slot = 0;
  };
  std::vector<RunningSlot> RunningSlots();

  // Cancels every unfinished job; returns the ones that were running (their workers should
  // stop them). Throws StoreError for an unknown campaign.
  std::vector<RunningJob> CancelCampaign(const std::string& campaign_id);
  // Puts every failed or cancelled job back (attempt + 1, a fresh retry budget) and reactivates
  // the campaign. Returns how many jobs it revived.
  int RetryFailed(const std::string& campaign_id);

  // Throws StoreError for an unknown campaign.
  CampaignProgress Progress(const std::string& campaign_id);
  std::vector<CampaignProgress> AllProgress();
  std::optional<JobRecord> GetJob(const std::string& job_id);
  // One row per succeeded eval job, by scenario (campaign order), label, rng_run.
  std::vector<MetricRow> Metrics(const std::string& campaign_id);
  // One row per UAV of each succeeded eval, in the order of Metrics, then by UAV.
  std::vector<UavMetricRow> UavMetrics(const std::string& campaign_id);
  // Workers: UpsertWorker sets alive and last_seen = now; SetWorkerState marks it lost or
  // stopped (no-op for an unknown id); MarkAllWorkersLost is the coordinator's start (it knows
  // nothing alive until DDS tells it).
  void UpsertWorker(const WorkerRecord& worker);
  void SetWorkerState(const std::string& worker_id, const std::string& state);
  void MarkAllWorkersLost();
  std::vector<WorkerRecord> ListWorkers();
  // Keeps the latest progress line of a running attempt (ignored otherwise); cleared when the
  // attempt ends.
  void SetProgress(const std::string& job_id, int attempt, const std::string& line,
                   const std::string& worker_id = "");
  // Throw StoreError for an unknown campaign.
  std::vector<RunningJobView> RunningJobs(const std::string& campaign_id);
  CampaignTiming Timing(const std::string& campaign_id);
  std::vector<FailedJob> FailedJobs(const std::string& campaign_id);
  // The campaign's spec with only its top-level `key` ({} when the spec has none), read out by
  // SQLite: a spec lists every RngRun, and a 100k-run list need not be parsed to get at the
  // scenarios. nullopt for an unknown campaign.
  std::optional<nlohmann::json> CampaignSpecPart(const std::string& campaign_id,
                                                 const std::string& key);

  // The artifacts of a campaign (or of one job, given its id), by job then name.
  std::vector<ArtifactRecord> Artifacts(const std::string& campaign_or_job_id);

 private:
  double Now() const;
  JobUpdate FailAttempt(const std::string& job_id, int attempt, int max_attempts,
                        const std::string& error);
  void UpdateCampaignState(const std::string& campaign_id);
  // Whether an eval at an offset around `job_id`'s position depends on it.
  bool HasOffsetDependants(const std::string& job_id);
  // Writes the files beside the database and lists them. Throws (files or rows).
  void StoreArtifacts(const std::string& job_id, const std::vector<ArtifactFile>& artifacts);
  void RequireCampaign(const std::string& campaign_id);
  // The result cache (results_store_cache.cc). A ready job whose content is known takes the
  // result of a succeeded job of the same content, or waits for an identical ready or running
  // one (cache_twin), unless its campaign was submitted with --no-cache.
  void ResolveFromCache(const std::string& job_id);
  // Serves the jobs that waited for `job_id`, which just succeeded.
  void ServeWaiting(const std::string& job_id);
  // Settles a ready job with the result (and artifacts) of the succeeded job `source`.
  void ServeFrom(const std::string& job_id, int attempt, const std::string& source);

  std::unique_ptr<Database> db_;
  StoreOptions options_;
};

}  // namespace rlpos
