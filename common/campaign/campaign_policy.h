#pragma once
// The named policies of a campaign's "positioners" ({"rl": {"policy": FOLDER, "name": N}}):
// each folder packed by its source, its files checked where it is cheap (JSON that parses,
// scenario.json a valid scenario, policy.json of the TorchScript format) and its scenario
// compared with every campaign scenario (scenario/scenario_contradiction.h), so that a policy
// that cannot place a UAV there is refused when the campaign is read, not on a worker.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/campaign/campaign_spec.h"

namespace rlpos {

// The objects of the positioners list `v` at `path` (its names are ReadCanonicalList's), at
// most kMaxCampaignPolicies, their names distinct. Throws ConfigError at the entry.
std::vector<CampaignPolicy> ReadPolicies(const nlohmann::json& v, const std::string& path,
                                         const PolicySource& source,
                                         const std::vector<CampaignScenario>& scenarios);

// The objects of "track"'s positioners list `v` at `path`, added to `policies` (marked tracked;
// a folder listed in both lists is one policy, placed and tracked). Each must be a policy for
// any scenario in the trained format (track flies it from where the UAVs are at every
// decision), and fit every scenario but for env.decision_interval, which a track run sets.
// Throws ConfigError at the entry.
void ReadTrackPolicies(const nlohmann::json& v, const std::string& path, const PolicySource& source,
                       const std::vector<CampaignScenario>& scenarios,
                       std::vector<CampaignPolicy>& policies);

}  // namespace rlpos
