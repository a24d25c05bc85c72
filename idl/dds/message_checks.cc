#include "idl/dds/message_checks.h"

#include "common/hash/sha256.h"
#include "common/wire/identifiers.h"
#include "common/wire/limits.h"

namespace rlpos {
namespace {

bool IsPrintable(const std::string& text, std::size_t max) {
  if (text.size() > max)
    return false;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 && c != '\t')
      return false;
  }
  return true;
}

}  // namespace

std::string CheckWorkerStatus(const msg::WorkerStatus& s) {
  if (!wire::IsSafeName(s.worker_id, wire::kMaxNameLength))
    return "bad worker_id";
  if (!IsPrintable(s.host, wire::kMaxNameLength))
    return "bad host";
  if (s.slots < 1 || s.slots > wire::kMaxSlots)
    return "slots out of 1..1024";
  if (s.busy < 0 || s.busy > s.slots)
    return "busy out of 0..slots";
  if (s.jobs.size() > static_cast<std::size_t>(s.slots))
    return "more jobs than slots";
  for (const auto& key : s.jobs) {
    const auto hash = key.rfind('#');
    if (hash == std::string::npos || !wire::IsSafePath(key.substr(0, hash), wire::kMaxIdLength)) {
      return "bad job key";
    }
  }
  return "";
}

std::string CheckJobEvent(const msg::JobEvent& e) {
  if (!wire::IsSafePath(e.job_id, wire::kMaxIdLength))
    return "bad job_id";
  if (e.attempt < 1 || e.attempt > wire::kMaxAttempt)
    return "attempt out of range";
  if (!wire::IsSafeName(e.worker_id, wire::kMaxNameLength))
    return "bad worker_id";
  if (e.slot < 0 || e.slot >= wire::kMaxSlots)
    return "slot out of 0..1023";
  switch (e.state) {
    case msg::JobState::kStarted:
    case msg::JobState::kProgress:
    case msg::JobState::kFailed:
      if (!e.result_json.empty())
        return "a result with a state that has none";
      break;
    case msg::JobState::kSucceeded:
      if (e.result_json.empty())
        return "success without a result";
      break;
    default:
      return "unknown state";
  }
  if (e.result_json.size() > wire::kMaxResultJson)
    return "result too large";
  if (!e.artifacts.empty()) {
    if (e.state != msg::JobState::kSucceeded)
      return "artifacts with a state that has none";
    if (std::string problem = CheckArtifacts(e.artifacts); !problem.empty())
      return problem;
  }
  if (e.message.size() > wire::kMaxMessage)
    return "message too long";
  const Provenance& p = e.provenance;
  for (const std::string* field :
       {&p.host, &p.rlpos_version, &p.ns3_version, &p.torch_version, &p.cyclonedds_version}) {
    if (!IsPrintable(*field, wire::kMaxNameLength))
      return "bad provenance";
  }
  if (!p.scenario_sha256.empty() && !IsSha256Hex(p.scenario_sha256))
    return "bad scenario_sha256";
  return "";
}

std::string CheckCampaignRequest(const msg::CampaignRequest& r) {
  if (!wire::IsSafeName(r.request_id, wire::kMaxIdLength))
    return "bad request_id";
  switch (r.kind) {
    case msg::RequestKind::kSubmit:
      if (!r.campaign_id.empty())
        return "a submit names no campaign id";
      if (r.campaign_json.size() > wire::kMaxCampaignJson)
        return "campaign too large";
      if (r.scenarios.size() > wire::kMaxCampaignScenarios)
        return "too many scenario files";
      for (const auto& s : r.scenarios) {
        if (s.file.empty() || !IsPrintable(s.file, wire::kMaxScenarioFileName)) {
          return "bad scenario file name";
        }
        if (s.document.size() > wire::kMaxScenarioDocument)
          return "scenario document too large";
      }
      if (r.policies.size() > wire::kMaxPolicyFolders)
        return "too many policies";
      for (const auto& p : r.policies) {
        if (p.folder.empty() || !IsPrintable(p.folder, wire::kMaxScenarioFileName))
          return "bad policy folder name";
        // The files are held to a bundle's rules (names, bounds) when the campaign is planned;
        // here only what a sample may hold at all.
        if (p.files.size() > wire::kMaxPolicyFiles)
          return "too many policy files";
        std::size_t total = 0;
        for (const auto& f : p.files) {
          total += f.data.size();
          if (total > wire::kMaxPolicyFileBytes)
            return "policy too large";
        }
      }
      break;
    case msg::RequestKind::kCancel:
    case msg::RequestKind::kRetry:
      if (!wire::IsSafeName(r.campaign_id, wire::kMaxCampaignIdLength))
        return "bad campaign_id";
      if (!r.campaign_json.empty() || !r.scenarios.empty() || !r.policies.empty())
        return "a cancel or retry with a campaign";
      break;
    default:
      return "unknown request kind";
  }
  return "";
}

std::string CheckCampaignReply(const msg::CampaignReply& reply, const std::string& request_id) {
  if (reply.request_id != request_id)
    return "a reply to another request";
  if (!reply.campaign_id.empty() &&
      !wire::IsSafeName(reply.campaign_id, wire::kMaxCampaignIdLength)) {
    return "bad campaign_id";
  }
  if (reply.jobs < 0)
    return "negative job count";
  if (!IsPrintable(reply.message, wire::kMaxMessage))
    return "bad message";
  return "";
}

}  // namespace rlpos
