#pragma once
// Checks of received messages before anything uses them: bounds, known kinds, plausible
// numbers, safe identifiers. Each returns "" for a good message, else the reason to drop it (one
// line, safe to log). Pure functions: no DDS, so that they are unit- and fuzz-tested alone.
// Job assignments are checked by CheckJobOrder (common/wire/job_order.h), which also parses
// their scenario.
#include <string>

#include "idl/dds/messages.h"

namespace rlpos {

std::string CheckWorkerStatus(const msg::WorkerStatus& status);
std::string CheckJobEvent(const msg::JobEvent& event);
std::string CheckCampaignRequest(const msg::CampaignRequest& request);
// The reply to `request_id` (what a client expects).
std::string CheckCampaignReply(const msg::CampaignReply& reply, const std::string& request_id);

}  // namespace rlpos
