#pragma once
// The rows the store's classes hand out: jobs as the ledger schedules them, and campaigns,
// jobs and workers as status, results and reports read them.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/campaign/expansion.h"

namespace rlpos {

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

// What a RecordSuccess (store/result_recorder.h) / RecordFailure (store/job_ledger.h) did.
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
  std::int64_t id = 0;  // its rowid: how the campaign page names it (never by its path)
  std::string job_id, job_key, scenario, label, name, path, sha256;
  std::int64_t bytes = 0;
  std::optional<std::string> cached_from;  // the job was served from this one's result
};

struct FailedJob {
  std::string key;
  int attempts = 0;
  std::string error;
};

// Where a job runs: its worker, campaign and slot.
struct RunningSlot {
  std::string worker_id, campaign_id;
  int slot = 0;
};

}  // namespace rlpos
