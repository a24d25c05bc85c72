#include "common/campaign/campaign_id.h"

#include <cstdio>

namespace rlpos {

std::uint64_t Fnv1a64(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string CampaignId(const CampaignSpec& spec) {
  // nlohmann::json keeps object keys sorted, so dump() is canonical.
  return CampaignIdOfSpecText(ToJsonText(spec));
}

std::string CampaignIdOfSpecText(const std::string& spec_text) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(Fnv1a64(spec_text)));
  return std::string(hex, 12);
}

std::string JobId(const std::string& campaign_id, const std::string& key) {
  return campaign_id + "/" + key;
}

}  // namespace rlpos
