#pragma once
// rlpos-worker's loop: announce itself (WorkerStatus, automatic liveliness), take the
// assignments of its slots, check each (CheckJobOrder: bounds, kinds, the scenario parsed, a
// timeout in (0, cap]) before anything is written, run it in a child rlpos-sim (JobAttempt),
// report progress / succeeded / failed on the slot's JobEvent, and stop a job whose slot the
// coordinator empties (disposes) or gives another job. An emptied slot also disposes its event:
// the worker keeps nothing per finished job.
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/logging/drop_log.h"
#include "idl/dds/messages.h"
#include "idl/dds/participant.h"
#include "worker/daemon/job_attempt.h"

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
  // Stops what the slot runs and forgets it; `why` goes in the log.
  void Empty(int slot, const std::string& why);
  void Start(int slot, msg::JobAssignment assignment);
  // Starts an assignment from the followed coordinator unless its slot holds that attempt
  // already. True when it stopped a running job to do so.
  bool Consider(msg::JobAssignment assignment);
  bool FromCoordinator(const std::string& sender);
  msg::JobEvent EventOf(int slot) const;  // its key and job, to fill in

  WorkerOptions options_;
  Provenance build_;  // this build and host, sent with each result
  Participant participant_;
  std::unique_ptr<Endpoints> dds_;
  // What each slot holds: the attempt the coordinator put there, until it empties the slot (a
  // republished assignment, after a coordinator restart, never runs twice).
  struct Slot {
    std::string job_id;  // "": empty
    int attempt = 0;
    std::unique_ptr<JobAttempt> run;  // while its child runs
    std::string progress_sent;
    bool announced = false;  // its event instance holds an event (disposed when emptied)
  };
  std::vector<Slot> slots_;
  // Assignments from a coordinator not followed yet, by slot (TakeAssignments).
  struct PendingAssignment {
    msg::JobAssignment assignment;
    std::string sender;
    std::chrono::steady_clock::time_point since;
  };
  static constexpr std::chrono::seconds kPendingFor{30};
  std::map<int, PendingAssignment> pending_;
  // The participant whose assignments this worker follows: the first to send it a job, until
  // that participant's writer is gone (a restarted coordinator is a new participant).
  std::string coordinator_;
  DropLog dropped_{"job assignment"};
};

}  // namespace rlpos
