#pragma once
// rlpos-worker's loop: announce itself (WorkerStatus, automatic liveliness), take the
// assignments addressed to it, run each in a child rlpos-sim (JobAttempt), report started /
// progress / succeeded / failed (JobEvent), and stop a job whose assignment is disposed.
#include <map>
#include <memory>
#include <set>
#include <string>

#include "daemon/job_attempt.h"
#include "dds/participant.h"

namespace rlpos {

struct WorkerOptions {
  std::string id;  // unique on the DDS domain
  int slots = 1;
  std::string work_dir;    // attempt folders go below
  std::string sim_binary;  // rlpos-sim
  double progress_period_s = 2.0;
};

class WorkerDaemon {
 public:
  WorkerDaemon(WorkerOptions options, const DdsOptions& dds);
  ~WorkerDaemon();
  // Runs until StopRequested(); stops running children on the way out.
  void Run();

 private:
  struct Endpoints;
  void PublishStatus();
  void TakeAssignments();
  void PollJobs();
  void ReportProgress();

  WorkerOptions options_;
  Participant participant_;
  std::unique_ptr<Endpoints> dds_;
  std::map<std::string, std::unique_ptr<JobAttempt>> running_;  // by job id
  std::map<std::string, std::string> progress_sent_;            // by job id
  std::set<std::string> seen_;  // "<job id>#<attempt>" this worker started: never run twice
};

}  // namespace rlpos
