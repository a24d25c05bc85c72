#pragma once
// Which ready job goes to which live worker: pure, deterministic (same inputs, same output).
//  - slots: a worker never gets more jobs than its free slots (slots - busy);
//  - fair between campaigns: each pick goes to the campaign with the fewest jobs running
//    (counting this round's picks), so a big campaign cannot starve a small one; ties go to
//    the campaign listed first (the store lists the oldest first);
//  - within a campaign, train jobs first (they are the long ones and unlock six evals per
//    run), then position jobs, then evals, each in the store's (expansion) order;
//  - spread: each job goes to the worker with the most free slots, ties to the lower id.
#include <map>
#include <string>
#include <vector>

#include "common/store/store_records.h"

namespace rlpos {

struct WorkerSlots {
  std::string id;
  int slots = 1;  // jobs it runs at once
  int busy = 0;   // jobs it runs now
};

struct Assignment {
  ReadyJob job;
  std::string worker_id;
  int slot = 0;  // which of the worker's slots: set by the Scheduler, which knows the free ones
};

// `running_by_campaign`: jobs running now per campaign id (absent = 0).
std::vector<Assignment> AssignJobs(const std::vector<ReadyJob>& ready,
                                   const std::vector<WorkerSlots>& workers,
                                   const std::map<std::string, int>& running_by_campaign = {});

}  // namespace rlpos
