#pragma once
// One attempt of one job on this worker: its folder, the rlpos-sim child, the timeout, and the
// outcome the worker reports (the child's JSON, or an error that says why it failed).
#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/process/child_process.h"
#include "common/wire/artifacts.h"
#include "common/wire/job_order.h"

namespace rlpos {

struct JobOutcome {
  bool succeeded = false;
  std::string result_json;              // compact JSON printed by the child
  std::string error;                    // one line
  std::vector<ArtifactFile> artifacts;  // a train job's files, to send home
};

// The TrainArtifactNames() files in a train job's output folder, with their sha256. Throws
// std::runtime_error naming a file that is larger than the wire allows.
std::vector<ArtifactFile> ReadTrainArtifacts(const std::string& out_folder);

// <work_dir>/<job id with each path component made safe>/attempt<N>.
std::string AttemptFolder(const std::string& work_dir, const std::string& job_id, int attempt);

// The last non-empty lines of a child's stderr, joined by " | ", at most `max_chars`.
std::string TailOfLog(const std::string& file, int lines = 3, std::size_t max_chars = 400);

class JobAttempt {
 public:
  // `order` passed CheckJobOrder, which gave `scenario` (the effective document). Prepares the
  // folder, writes the scenario and starts the child. Throws std::runtime_error if it cannot.
  JobAttempt(JobOrder order, const nlohmann::json& scenario, const std::string& work_dir,
             const std::string& sim_binary);

  const JobOrder& order() const { return order_; }
  std::string Key() const;  // "<job id>#<attempt>"
  // Of the scenario file the child runs, as written.
  const std::string& scenario_sha256() const { return scenario_sha256_; }
  // Non-blocking: the outcome once the child ended or ran past its timeout (then killed).
  std::optional<JobOutcome> Poll();
  // Stops the child (the coordinator withdrew the job); no outcome is reported.
  void Stop();
  // The child's latest progress line on stderr ("" if none).
  std::string ProgressLine() const;

 private:
  JobOrder order_;
  std::string folder_;
  std::string scenario_sha256_;
  std::chrono::steady_clock::time_point started_;
  std::unique_ptr<ChildProcess> child_;
};

}  // namespace rlpos
