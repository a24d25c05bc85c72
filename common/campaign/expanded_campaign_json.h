#pragma once
// An expanded campaign as JSON: what `rlpos-campaign submit` sends the coordinator, so that the
// coordinator (maybe on another machine) needs neither the campaign file nor its scenarios.
#include <nlohmann/json.hpp>

#include "campaign/expansion.h"

namespace rlpos {

nlohmann::json ToJson(const ExpandedCampaign& campaign);
// Throws std::invalid_argument naming the first malformed field.
ExpandedCampaign ExpandedCampaignFromJson(const nlohmann::json& json);

}  // namespace rlpos
