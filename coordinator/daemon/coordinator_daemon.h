#pragma once
// rlpos-coordinator's loop. The results store is the memory; DDS is only the wire, and every
// sample from it is checked before use (bounds, kinds, plausibility, sender):
//  - campaign requests: submit sends a campaign and its scenario documents, which are validated
//    like `run` does, its jobs streamed into the store; cancel and retry name a campaign;
//  - worker statuses keep the set of live workers, each bound to the DDS participant that first
//    announced it; a lost lease (or a clean stop) sends the worker's running jobs back to ready;
//  - job events count only from the participant of the worker that holds the job's current
//    attempt; they are recorded exactly once per attempt, and the job's slot is then disposed,
//    which tells the worker the job is settled (the slot's instance serves its next job);
//  - each tick fails timed-out jobs and assigns ready jobs to free slots, each to a slot of its
//    own (jobs.slot), so the DDS instances are as many as the workers' slots.
// A dropped sample costs one rate-limited warning line and nothing else.
// After a restart it waits one grace period for the workers to reappear, then requeues the
// running jobs of workers that did not, and republishes the assignments of those that did (a
// worker ignores an attempt it already has).
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "common/campaign/campaign_request.h"
#include "common/logging/drop_log.h"
#include "common/process/file_lock.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "coordinator/scheduling/scheduler.h"
#include "idl/dds/messages.h"
#include "idl/dds/participant.h"

namespace rlpos {

struct CoordinatorOptions {
  std::string db_file;
  int max_infra_losses = 10;     // a job lost with its worker more often than this fails
  double tick_s = 0.25;          // scheduling period when nothing arrives
  double restart_grace_s = 5.0;  // wait for workers after start before judging running jobs
  SubmitLimits limits;           // what a submitted campaign may hold
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
    std::string participant;     // DDS participant GUID that announced it
    std::set<std::string> jobs;  // "<job id>#<attempt>" it reported
    std::string host;            // as last written to the workers table
    std::int64_t pid = 0;
    double written_at = 0;
  };
  static constexpr double kWorkerRowPeriodS = 1.0;
  static constexpr std::chrono::milliseconds kMinRound{50};
  struct Published {
    int attempt = 0;
    std::string worker_id;
    int slot = 0;
  };
  void HandleRequests();
  void HandleWorkerStatuses();
  // Returns how many samples it took.
  std::size_t HandleJobEvents();
  void HandleJobEvent(const msg::JobEvent& event, const std::string& sender);
  void AfterGrace();
  // The round's scheduling decisions, written to the store; PublishTick sends them.
  TickResult Schedule();
  void PublishTick(const TickResult& tick);
  // Empties the slots of a (re)joining worker that run jobs the store no longer gives it.
  void WithdrawStale(const std::string& worker_id, int slots, const std::vector<std::string>& jobs);
  void Publish(const ReadyJob& job, const std::string& worker_id, int slot);
  void Republish(const std::string& worker_id);
  // Empties the slot of a job this coordinator published (nothing for one it did not).
  void Withdraw(const std::string& job_id);
  void DisposeSlot(const std::string& worker_id, int slot);
  const std::string& ScenarioDocument(const std::string& campaign_id, const std::string& name);
  // A named policy kept beside the database (PoliciesDirOf), by its sha256; read once.
  std::optional<PolicyBundle> Policy(const std::string& sha256);
  double Now() const;

  CoordinatorOptions options_;
  ExclusiveFileLock lock_;  // one coordinator per database
  CoordinatorStore store_;
  Scheduler scheduler_;
  Participant participant_;
  std::unique_ptr<Endpoints> dds_;
  std::map<std::string, LiveWorker> live_;
  std::map<std::string, Published> published_;  // job id -> its live assignment
  // Events that came before their worker's status (HandleJobEvents), oldest first.
  struct DeferredEvent {
    msg::JobEvent event;
    std::string sender;
    double since = 0;
  };
  static constexpr double kEventDeferralS = 10.0;
  static constexpr std::size_t kMaxDeferredEvents = 4096;
  static constexpr std::size_t kMaxDeferredBytes = 64 * 1048576;  // results with artifacts
  std::vector<DeferredEvent> deferred_events_;
  std::size_t deferred_bytes_ = 0;
  std::map<std::string, std::map<std::string, std::string>> documents_;  // by campaign
  std::map<std::string, PolicyBundle> policies_;                         // by sha256
  DropLog dropped_requests_{"campaign request"}, refused_requests_{"campaign request"},
      dropped_statuses_{"worker status"}, dropped_events_{"job event"};
  double started_ = 0;
  bool grace_over_ = false;
};

}  // namespace rlpos
