#pragma once
// A campaign submitted over the network: the campaign file as written and the scenario files it
// names, as the client read them. The coordinator validates it with the same validator as
// `rlpos-campaign run` and plans it itself, so the campaign id is the hash of what it checked.
#include <cstddef>
#include <string>
#include <vector>

#include "common/campaign/expansion.h"
#include "common/campaign/submitted_policy.h"
#include "common/campaign/submitted_scenario.h"

namespace rlpos {

struct SubmitLimits {
  std::size_t max_request_bytes = 4u << 20;  // campaign + documents
  std::size_t max_jobs = 200000;
  std::size_t max_scenarios = 32;
};

// Throws std::invalid_argument with one line that says what is wrong (the reply's message):
// over a limit, malformed JSON, or the campaign's ConfigError with its JSON path.
CampaignPlan PlanSubmittedCampaign(const std::string& campaign_json,
                                   const std::vector<SubmittedScenario>& scenarios,
                                   const SubmitLimits& limits);
// With the named policies' folders, as packed by the client (each its own bound,
// kMaxPolicyBytes, outside max_request_bytes); a bundle that is not one (unknown file, too
// large, a format's file missing) refuses the campaign.
CampaignPlan PlanSubmittedCampaign(const std::string& campaign_json,
                                   const std::vector<SubmittedScenario>& scenarios,
                                   const std::vector<SubmittedPolicy>& policies,
                                   const SubmitLimits& limits);

// What a client sends for a campaign file: its text and the scenario files it names. Reads
// and validates the campaign first (ConfigError as ReadCampaignFile).
struct CampaignSubmission {
  CampaignPlan campaign;  // as the client plans it (its id is the one to expect)
  std::string campaign_json;
  std::vector<SubmittedScenario> scenarios;
  std::vector<SubmittedPolicy> policies;  // the named policies' folders, packed
};
CampaignSubmission ReadCampaignSubmission(const std::string& campaign_file);

}  // namespace rlpos
