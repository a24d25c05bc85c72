#pragma once
// Stable campaign ids: the same resolved campaign (scenario contents included) always gets the
// same id, so re-submitting it finds the jobs already in the store.
#include <cstdint>
#include <string>

#include "common/campaign/campaign_spec.h"

namespace rlpos {

std::uint64_t Fnv1a64(const std::string& bytes);

// First 12 hex digits of FNV-1a 64 over the canonical JSON (ToJson(spec).dump(), keys sorted).
std::string CampaignId(const CampaignSpec& spec);
// The same, of the canonical JSON text itself.
std::string CampaignIdOfSpecText(const std::string& spec_text);

// "<campaign id>/<key>".
std::string JobId(const std::string& campaign_id, const std::string& key);

}  // namespace rlpos
