// submit, cancel, retry: requests to the coordinator over DDS.
#include <iostream>
#include <nlohmann/json.hpp>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "coordinator/cli/campaign_client.h"
#include "coordinator/cli/campaign_commands.h"

namespace rlpos {
namespace {

// A refusal by the coordinator (unknown campaign id, ...) is bad input on our side.
int Refused(const msg::CampaignReply& reply) {
  std::cerr << "rlpos-campaign: error: the coordinator refused: " << reply.message << "\n";
  return kExitBadInput;
}

// cancel and retry: a request that names an existing campaign.
msg::CampaignReply RequestOnCampaign(msg::RequestKind kind, const std::string& campaign_id,
                                     const DdsOptions& dds, double timeout_s) {
  msg::CampaignRequest request;
  request.kind = kind;
  request.campaign_id = campaign_id;
  return SendCampaignRequest(dds, request, timeout_s);
}

}  // namespace

int SubmitCampaign(const std::string& campaign_file, bool use_cache, const DdsOptions& dds,
                   double timeout_s) {
  const CampaignSubmission submission = ReadCampaignSubmission(campaign_file);
  const CampaignPlan& campaign = submission.campaign;
  const msg::CampaignReply reply = SendCampaignRequest(
      dds, SubmitRequest(submission, use_cache), timeout_s, {}, [&](const msg::CampaignReply& r) {
        return !r.ok || r.campaign_id == campaign.id
                   ? std::string()
                   : "the coordinator expanded the campaign to " + r.campaign_id + ", not " +
                         campaign.id + " (different rlpos versions?)";
      });
  if (!reply.ok)
    return Refused(reply);
  std::cout << reply.campaign_id << "\n";
  std::cerr << (reply.created ? "submitted " : "already submitted ") << campaign.name << ": "
            << reply.jobs << " jobs\n";
  return kExitOk;
}

int CancelCampaign(const std::string& campaign_id, const DdsOptions& dds, double timeout_s) {
  const auto reply = RequestOnCampaign(msg::RequestKind::kCancel, campaign_id, dds, timeout_s);
  if (!reply.ok)
    return Refused(reply);
  std::cerr << "cancelled " << campaign_id << " (" << reply.jobs << " running job(s) stopped)\n";
  return kExitOk;
}

int RetryCampaign(const std::string& campaign_id, const DdsOptions& dds, double timeout_s) {
  const auto reply = RequestOnCampaign(msg::RequestKind::kRetry, campaign_id, dds, timeout_s);
  if (!reply.ok)
    return Refused(reply);
  std::cerr << "retrying " << reply.jobs << " job(s) of " << campaign_id << "\n";
  return kExitOk;
}

}  // namespace rlpos
