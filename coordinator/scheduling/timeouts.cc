#include "coordinator/scheduling/timeouts.h"

#include "common/scenario/number_text.h"

namespace rlpos {

std::string TimeoutMessage(double timeout_s) {
  return "timed out after " + FormatNumber(timeout_s) + " s";
}

std::vector<TimedOut> FindTimedOut(const std::vector<RunningJob>& running, double now) {
  std::vector<TimedOut> out;
  for (const auto& job : running) {
    if (now - job.started_at > job.timeout_s)
      out.push_back({job, TimeoutMessage(job.timeout_s)});
  }
  return out;
}

}  // namespace rlpos
