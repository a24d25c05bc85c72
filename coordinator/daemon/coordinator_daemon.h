#pragma once
// rlpos-coordinator's loop. The results store is the memory; DDS is only the wire:
//  - campaign requests (submit, cancel, retry) are applied to the store and answered;
//  - worker statuses keep the set of live workers; a lost lease (or a clean stop) sends the
//    worker's running jobs back to ready;
//  - job events are recorded (exactly once per attempt, stale attempts ignored) and the
//    assignment is then disposed, which tells the worker the job is settled;
//  - each tick fails timed-out jobs and assigns ready jobs to free slots.
// After a restart it waits one grace period for the workers to reappear, then requeues the
// running jobs of workers that did not, and republishes the assignments of those that did (a
// worker ignores an attempt it already has).
#include <map>
#include <memory>
#include <set>
#include <string>

#include "dds/participant.h"
#include "process/file_lock.h"
#include "scheduling/scheduler.h"
#include "store/results_store.h"

namespace rlpos {

struct CoordinatorOptions {
  std::string db_file;
  double tick_s = 0.25;          // scheduling period when nothing arrives
  double restart_grace_s = 5.0;  // wait for workers after start before judging running jobs
};

class CoordinatorDaemon {
 public:
  CoordinatorDaemon(CoordinatorOptions options, const DdsOptions& dds);
  ~CoordinatorDaemon();
  // Runs until StopRequested().
  void Run();

 private:
  struct Endpoints;
  struct LiveWorker {
    WorkerSlots slots;
    std::set<std::string> jobs;  // "<job id>#<attempt>" it reported
  };
  void HandleRequests();
  void HandleWorkerStatuses();
  void HandleJobEvents();
  void AfterGrace();
  void Schedule();
  void Publish(const ReadyJob& job, const std::string& worker_id);
  void Withdraw(const std::string& job_id);
  const std::string& ScenarioDocument(const std::string& campaign_id, const std::string& name);
  double Now() const;

  CoordinatorOptions options_;
  ExclusiveFileLock lock_;  // one coordinator per database
  ResultsStore store_;
  Scheduler scheduler_;
  Participant participant_;
  std::unique_ptr<Endpoints> dds_;
  std::map<std::string, LiveWorker> live_;
  std::map<std::string, int> published_;  // job id -> attempt of its live assignment
  std::map<std::string, std::map<std::string, std::string>> documents_;  // by campaign
  double started_ = 0;
  bool grace_over_ = false;
};

}  // namespace rlpos
