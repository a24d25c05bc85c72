#include "coordinator/scheduling/scheduler.h"

#include <algorithm>
#include <map>
#include <set>

namespace rlpos {

TickResult Scheduler::Tick(const std::vector<WorkerSlots>& live_workers, double now) {
  TickResult result;
  if (now >= next_timeout_check_) {
    next_timeout_check_ = now + kTimeoutCheckS;
    for (auto& t : FindTimedOut(ledger_.ListRunning(), now)) {
      const JobUpdate update = ledger_.RecordFailure(t.job.id, t.job.attempt, t.error);
      if (update == JobUpdate::kRetrying || update == JobUpdate::kFailed) {
        result.timed_out.push_back(std::move(t));
      }
    }
  }

  std::map<std::string, int> by_worker;
  std::map<std::string, int> by_campaign;
  std::map<std::string, std::set<int>> taken;  // worker -> slots that run a job
  for (const auto& running : ledger_.RunningSlots()) {
    ++by_worker[running.worker_id];
    ++by_campaign[running.campaign_id];
    taken[running.worker_id].insert(running.slot);
  }
  std::vector<WorkerSlots> workers = live_workers;
  std::size_t free = 0;
  for (auto& w : workers) {
    w.busy = std::max(w.busy, by_worker[w.id]);
    free += static_cast<std::size_t>(std::max(0, w.slots - w.busy));
  }
  // Nothing to fill, nothing to read: a busy cluster costs no query per event.
  if (free == 0)
    return result;
  std::map<std::string, int> slots;
  for (const auto& w : workers)
    slots[w.id] = w.slots;
  // `free` per campaign is enough for any fair share of the free slots.
  for (auto& a : AssignJobs(ledger_.ListReady(free), workers, by_campaign)) {
    std::set<int>& used = taken[a.worker_id];
    int slot = 0;
    while (used.count(slot))
      ++slot;
    if (slot >= slots[a.worker_id])
      continue;  // not reached: AssignJobs gives no worker more jobs than free slots
    if (ledger_.MarkRunning(a.job.id, a.worker_id, slot, a.job.attempt)) {
      used.insert(slot);
      a.slot = slot;
      result.assigned.push_back(std::move(a));
    }
  }
  return result;
}

std::vector<std::string> Scheduler::WorkerLost(const std::string& worker_id) {
  return ledger_.RequeueWorker(worker_id);
}

}  // namespace rlpos
