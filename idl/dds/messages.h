#pragma once
// The C++ side of rlpos_messages.idl: plain structs the daemons use; message_fields.h lists each
// one's fields against the generated C type once, for both directions, so no other file sees
// the C API. A job travels as the typed JobOrder of common/wire/job_order.h.
#include <cstdint>
#include <string>
#include <vector>

#include "common/campaign/submitted_policy.h"
#include "common/campaign/submitted_scenario.h"
#include "common/provenance/provenance.h"
#include "common/wire/artifacts.h"
#include "common/wire/job_order.h"

namespace rlpos::msg {

struct WorkerStatus {
  std::string worker_id, host;
  std::int64_t pid = 0;
  int slots = 1, busy = 0;
  std::vector<std::string> jobs;  // "<job id>#<attempt>"
};

struct JobAssignment {
  std::string worker_id;  // the worker it is for
  int slot = 0;           // which of its slots runs it
  JobOrder order;
};

enum class JobState { kStarted, kProgress, kSucceeded, kFailed };

struct JobEvent {
  std::string worker_id;
  int slot = 0;  // the slot that runs the attempt
  std::string job_id;
  int attempt = 1;
  JobState state = JobState::kStarted;
  std::string result_json, message;
  Provenance provenance;                // kSucceeded, kFailed
  std::vector<ArtifactFile> artifacts;  // kSucceeded of a train job
};

enum class RequestKind { kSubmit, kCancel, kRetry };

struct CampaignRequest {
  std::string request_id;
  RequestKind kind = RequestKind::kSubmit;
  std::string campaign_id;
  std::string campaign_json;                 // submit: the campaign file as written
  std::vector<SubmittedScenario> scenarios;  // submit: the scenario files, as the client read them
  bool no_cache = false;                     // submit: every job runs, none takes a cached result
  std::vector<SubmittedPolicy> policies;     // submit: the named policies' folders, packed
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
