#pragma once
// rlpos-campaign's side of the campaign requests: send one request to the coordinator over DDS
// and wait for its reply. The coordinator is the only writer of the database, so submit,
// cancel and retry go through it.
#include <functional>
#include <stdexcept>
#include <string>

#include "common/campaign/campaign_request.h"
#include "idl/dds/messages.h"
#include "idl/dds/participant.h"

namespace rlpos {

// No coordinator answered in time (exit code 4 of rlpos-campaign).
class NoCoordinatorError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "DDS domain 0" or "DDS domain 7, loopback tag T".
std::string DescribeDds(const DdsOptions& options);

// The submit request of a campaign read by ReadCampaignSubmission; `use_cache` false: every
// job runs (--no-cache).
msg::CampaignRequest SubmitRequest(const CampaignSubmission& submission, bool use_cache);

// What a submit's reply must say beyond CheckCampaignReply: "" to accept it, else why not.
using ReplyCheck = std::function<std::string(const msg::CampaignReply&)>;

// Fills in request_id; throws NoCoordinatorError when no coordinator is matched or answers
// within `timeout_s`. `while_waiting` is called every few tens of ms while it waits (the
// embedded runner checks there that its coordinator is still alive; it may throw). A reply
// that `check` refuses is not the answer: it keeps waiting (on an unsecured network anyone can
// forge a reply) and, if no acceptable one comes, throws std::runtime_error with the reason.
msg::CampaignReply SendCampaignRequest(const DdsOptions& dds, msg::CampaignRequest request,
                                       double timeout_s,
                                       const std::function<void()>& while_waiting = {},
                                       const ReplyCheck& check = {});

}  // namespace rlpos
