#pragma once
// The C++ side of rlpos_messages.idl: plain structs the daemons use; topics.cc converts them to
// and from the generated C types, so no other file sees the C API.
#include <cstdint>
#include <string>
#include <vector>

namespace rlpos::msg {

struct WorkerStatus {
  std::string worker_id, host;
  std::int64_t pid = 0;
  int slots = 1, busy = 0;
  std::vector<std::string> jobs;  // "<job id>#<attempt>"
};

struct JobAssignment {
  std::string job_id;
  int attempt = 1;
  std::string worker_id, campaign_id;
  std::vector<std::string> argv;
  std::string scenario_document;
  double timeout_s = 0;
};

enum class JobState { kStarted, kProgress, kSucceeded, kFailed };

struct JobEvent {
  std::string job_id;
  int attempt = 1;
  std::string worker_id;
  JobState state = JobState::kStarted;
  std::string result_json, message;
};

enum class RequestKind { kSubmit, kCancel, kRetry };

struct CampaignRequest {
  std::string request_id;
  RequestKind kind = RequestKind::kSubmit;
  std::string campaign_id, campaign_json;
};

struct CampaignReply {
  std::string request_id;
  bool ok = false;
  std::string campaign_id;
  int jobs = 0;
  bool created = false;
  std::string message;
};

}  // namespace rlpos::msg
