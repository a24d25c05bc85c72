#pragma once
// Shared helpers of the process tests: the file helpers, waiting with a deadline, and which
// processes of a group are still alive.
#include <sys/types.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/temp_dir.h"
#include "tests/support/wait_for.h"

namespace rlpos::testing {

// Pids of the processes in group `pgid` that have not ended. Zombies count as ended: the
// orphans of a killed group are reaped by whoever adopted them, maybe not at once.
std::vector<pid_t> LiveProcessesOfGroup(pid_t pgid);

}  // namespace rlpos::testing
