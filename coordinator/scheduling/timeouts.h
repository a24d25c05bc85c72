#pragma once
// Timeout bookkeeping: a running job older than its timeout is failed (the store then retries
// it while attempts remain) and its worker is told to stop it. Also the safety net for a worker
// that died while no coordinator watched it (after a coordinator restart).
#include <string>
#include <vector>

#include "common/store/store_records.h"

namespace rlpos {

struct TimedOut {
  RunningJob job;
  std::string error;  // "timed out after N s"
};

std::string TimeoutMessage(double timeout_s);

// Jobs that have run longer than their timeout at `now` (same clock as the store's).
std::vector<TimedOut> FindTimedOut(const std::vector<RunningJob>& running, double now);

}  // namespace rlpos
