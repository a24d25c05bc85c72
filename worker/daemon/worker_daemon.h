#pragma once
// rlpos-worker's loop: announce itself (WorkerStatus, automatic liveliness), take the
// assignments addressed to it, check each (CheckJobOrder: bounds, kinds, the scenario parsed,
// a timeout in (0, cap], a free slot) before anything is written, run it in a child rlpos-sim
// (JobAttempt), report started / progress / succeeded / failed (JobEvent), and stop a job whose
// assignment is disposed. A disposed assignment also ends the job's event instance here: the
// worker keeps nothing per finished job.
#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "daemon/job_attempt.h"
#include "dds/messages.h"
#include "dds/participant.h"
#include "logging/drop_log.h"

namespace rlpos {

struct WorkerOptions {
  std::string id;  // unique on the DDS domain
  int slots = 1;
  std::string work_dir;    // attempt folders go below
  std::string sim_binary;  // rlpos-sim
  double progress_period_s = 2.0;
  double max_timeout_s = 7 * 86400.0;  // longest job timeout it accepts
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
  void Settle(const std::string& job_id);
  void Start(msg::JobAssignment assignment);
  // Starts an assignment from the followed coordinator unless it has that attempt already.
  void Consider(msg::JobAssignment assignment);
  bool FromCoordinator(const std::string& sender);

  WorkerOptions options_;
  Provenance build_;  // this build and host, sent with each result
  Participant participant_;
  std::unique_ptr<Endpoints> dds_;
  std::map<std::string, std::unique_ptr<JobAttempt>> running_;  // by job id
  std::map<std::string, std::string> progress_sent_;            // by job id
  // Attempts this worker took, by job id, until the coordinator settles the job: a republished
  // assignment (coordinator restart) never runs twice.
  std::map<std::string, int> taken_;
  // Jobs whose event instance this worker wrote (progress, result): unregistered when settled.
  std::set<std::string> announced_;
  // Assignments from a coordinator not followed yet, by job id (TakeAssignments).
  struct PendingAssignment {
    msg::JobAssignment assignment;
    std::string sender;
    std::chrono::steady_clock::time_point since;
  };
  static constexpr std::chrono::seconds kPendingFor{30};
  static constexpr std::size_t kMaxPending = 1024;
  std::map<std::string, PendingAssignment> pending_;
  // The participant whose assignments this worker follows: the first to send it a job, until
  // that participant's writer is gone (a restarted coordinator is a new participant).
  std::string coordinator_;
  DropLog dropped_{"job assignment"};
};

}  // namespace rlpos
