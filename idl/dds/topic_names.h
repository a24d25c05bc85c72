#pragma once
// The DDS topic names: the contract between the daemons, and what the DDS Security permissions
// grant per role.
namespace rlpos::topic {

inline constexpr const char* kWorkerStatus = "rlpos_worker_status";
inline constexpr const char* kJobAssignment = "rlpos_job_assignment";
inline constexpr const char* kJobEvent = "rlpos_job_event";
inline constexpr const char* kCampaignRequest = "rlpos_campaign_request";
inline constexpr const char* kCampaignReply = "rlpos_campaign_reply";

}  // namespace rlpos::topic
