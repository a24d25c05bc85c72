#pragma once
// One scheduling step of the coordinator over the results store, with no DDS: the daemon calls
// Tick() when workers report or jobs finish (and on a timer), publishes the assignments, and
// tells the workers of timed-out jobs to stop them. The store stays the source of truth: every
// decision is written to it before the daemon acts on it.
#include <string>
#include <vector>

#include "common/store/job_ledger.h"
#include "coordinator/scheduling/assignment.h"
#include "coordinator/scheduling/timeouts.h"

namespace rlpos {

struct TickResult {
  std::vector<TimedOut> timed_out;   // failed in the store: their workers should stop them
  std::vector<Assignment> assigned;  // marked running in the store: send them to the workers
};

class Scheduler {
 public:
  explicit Scheduler(JobLedger& ledger) : ledger_(ledger) {}

  // Fails timed-out jobs (looked for at most once per kTimeoutCheckS), then assigns ready jobs
  // to `live_workers`, each to the lowest slot of its worker that runs nothing in the store. A
  // worker's busy count is the larger of what it reported and what the store has running on it.
  TickResult Tick(const std::vector<WorkerSlots>& live_workers, double now);
  // Timeouts are minutes; the coordinator ticks hundreds of times a second.
  static constexpr double kTimeoutCheckS = 1.0;

  // The worker's lease was lost: its running jobs go back to ready (or fail when out of
  // attempts). Returns their ids.
  std::vector<std::string> WorkerLost(const std::string& worker_id);

 private:
  JobLedger& ledger_;
  double next_timeout_check_ = 0;
};

}  // namespace rlpos
