#include "scheduling/scheduler.h"

#include <algorithm>
#include <map>

namespace rlpos {

TickResult Scheduler::Tick(const std::vector<WorkerSlots>& live_workers, double now) {
  TickResult result;
  for (auto& t : FindTimedOut(store_.ListRunning(), now)) {
    const JobUpdate update = store_.RecordFailure(t.job.id, t.job.attempt, t.error);
    if (update == JobUpdate::kRetrying || update == JobUpdate::kFailed) {
      result.timed_out.push_back(std::move(t));
    }
  }

  std::map<std::string, int> by_worker;
  std::map<std::string, int> by_campaign;
  for (const auto& job : store_.ListRunning()) {
    ++by_worker[job.worker_id];
    ++by_campaign[job.campaign_id];
  }
  std::vector<WorkerSlots> workers = live_workers;
  for (auto& w : workers) w.busy = std::max(w.busy, by_worker[w.id]);

  for (auto& a : AssignJobs(store_.ListReady(), workers, by_campaign)) {
    if (store_.MarkRunning(a.job.id, a.worker_id, a.job.attempt)) {
      result.assigned.push_back(std::move(a));
    }
  }
  return result;
}

std::vector<std::string> Scheduler::WorkerLost(const std::string& worker_id) {
  return store_.RequeueWorker(worker_id);
}

}  // namespace rlpos
