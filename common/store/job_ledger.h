#pragma once
// The job ledger: campaigns and the lifecycle of their jobs (states, attempts, the leases of
// workers), over the shared StoreDb. Every operation is one transaction.
//
// Job states:  pending   waiting for its dependency to succeed
//              ready     runnable (no dependency, or it succeeded); a failed attempt with
//                        attempts left comes back here with attempt + 1
//              running   assigned to a worker for one attempt
//              succeeded / failed / cancelled   final until RetryFailed
// Exactly-once: a result counts only for the job's current attempt while it is running, and a
// succeeded job is final, so a late, duplicate or stale result never changes anything.
// A success is recorded by ResultRecorder (store/result_recorder.h).
#include <string>
#include <vector>

#include "common/campaign/expansion.h"
#include "common/store/store_records.h"

namespace rlpos {

class Database;
class ResultCache;
class StoreDb;

class JobLedger {
 public:
  // `cache` serves the jobs that Submit and RetryFailed make ready, when it knows their result.
  JobLedger(StoreDb& store, ResultCache& cache);

  // Inserts the campaign and its jobs; re-submitting the same campaign is a no-op.
  SubmitResult Submit(const CampaignPlan& campaign);

  // Ready jobs of active campaigns: oldest campaign first, then expansion order; at most
  // `per_campaign` of each (0 = all).
  std::vector<ReadyJob> ListReady(std::size_t per_campaign = 0);
  // ready -> running for this attempt; false if the job is not ready at that attempt.
  bool MarkRunning(const std::string& job_id, const std::string& worker_id, int slot, int attempt);
  // `worker_id` non-empty: only the worker that holds the attempt may settle it (else kStale).
  JobUpdate RecordFailure(const std::string& job_id, int attempt, const std::string& error,
                          const std::string& worker_id = "");
  // The worker is gone: each of its running jobs fails that attempt ("worker W was lost") and
  // goes back to ready while attempts remain. Returns the ids of the jobs it held.
  std::vector<std::string> RequeueWorker(const std::string& worker_id);
  std::vector<RunningJob> ListRunning();
  // Where the running jobs run: worker, campaign and slot of each (cheaper than ListRunning
  // each round).
  std::vector<RunningSlot> RunningSlots();
  // Keeps the latest progress line of a running attempt (ignored otherwise); cleared when the
  // attempt ends.
  void SetProgress(const std::string& job_id, int attempt, const std::string& line,
                   const std::string& worker_id = "");

  // Cancels every unfinished job; returns the ones that were running (their workers should
  // stop them). Throws StoreError for an unknown campaign.
  std::vector<RunningJob> CancelCampaign(const std::string& campaign_id);
  // Puts every failed or cancelled job back (attempt + 1, a fresh retry budget) and reactivates
  // the campaign. Returns how many jobs it revived.
  int RetryFailed(const std::string& campaign_id);

  // Workers: UpsertWorker sets alive and last_seen = now; SetWorkerState marks it lost or
  // stopped (no-op for an unknown id); MarkAllWorkersLost is the coordinator's start (it knows
  // nothing alive until DDS tells it).
  void UpsertWorker(const WorkerRecord& worker);
  void SetWorkerState(const std::string& worker_id, const std::string& state);
  void MarkAllWorkersLost();

  // Steps of the other writers' transactions (no transaction of their own).
  // The attempt failed: ready again with attempt + 1 while attempts remain, else failed with the
  // jobs that wait for it.
  JobUpdate FailAttempt(const std::string& job_id, int attempt, int max_attempts,
                        const std::string& error);
  // An active campaign with no pending, ready or running job is finished.
  void UpdateCampaignState(const std::string& campaign_id);

 private:
  void InsertJobs(const CampaignPlan& campaign, double now, int& seq,
                  std::vector<std::string>& cacheable);

  StoreDb& store_;
  Database* db_;
  ResultCache& cache_;
};

}  // namespace rlpos
