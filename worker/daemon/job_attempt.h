#pragma once
// One attempt of one job on this worker: its folder, the rlpos-sim child, the timeout, and the
// outcome the worker reports (the child's JSON, or an error that says why it failed).
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "process/child_process.h"

namespace rlpos {

struct JobAttemptSpec {
  std::string job_id;
  int attempt = 1;
  std::vector<std::string> argv;  // as the coordinator sent it ("rlpos-sim", placeholders)
  std::string scenario_document;  // written to the attempt's folder; "" keeps --scenario as is
  double timeout_s = 0;           // <= 0: none
};

struct JobOutcome {
  bool succeeded = false;
  std::string result_json;  // compact JSON printed by the child
  std::string error;        // one line
};

// <work_dir>/<job id with each path component made safe>/attempt<N>.
std::string AttemptFolder(const std::string& work_dir, const std::string& job_id, int attempt);

// The command line to run: argv[0] "rlpos-sim" -> `sim_binary`, {out_dir} -> <folder>/out,
// the --scenario argument -> <folder>/scenario.json when a document comes with the job.
std::vector<std::string> BindJobArgv(const JobAttemptSpec& spec, const std::string& folder,
                                     const std::string& sim_binary);

// The last non-empty lines of a child's stderr, joined by " | ", at most `max_chars`.
std::string TailOfLog(const std::string& file, int lines = 3, std::size_t max_chars = 400);

class JobAttempt {
 public:
  // Prepares the folder and starts the child. Throws std::runtime_error if it cannot.
  JobAttempt(JobAttemptSpec spec, const std::string& work_dir, const std::string& sim_binary);

  const JobAttemptSpec& spec() const { return spec_; }
  std::string Key() const;  // "<job id>#<attempt>"
  // Non-blocking: the outcome once the child ended or ran past its timeout (then killed).
  std::optional<JobOutcome> Poll();
  // Stops the child (the coordinator withdrew the job); no outcome is reported.
  void Stop();
  // The child's latest progress line on stderr ("" if none).
  std::string ProgressLine() const;

 private:
  JobAttemptSpec spec_;
  std::string folder_;
  std::chrono::steady_clock::time_point started_;
  std::unique_ptr<ChildProcess> child_;
};

}  // namespace rlpos
