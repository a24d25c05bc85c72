#include "coordinator/daemon/scenario_documents.h"

#include <stdexcept>

#include "common/campaign/campaign_spec.h"

namespace rlpos {

std::map<std::string, std::string> ScenarioDocumentsByName(const nlohmann::json& campaign_spec) {
  std::map<std::string, std::string> out;
  if (!campaign_spec.contains("scenarios") || !campaign_spec["scenarios"].is_array())
    return out;
  for (const auto& entry : campaign_spec["scenarios"]) {
    try {
      const nlohmann::json stated = StatedScenarioDocument(entry);
      // The parser's default name when the document has none; the document before its "set".
      out[stated.value("name", std::string("scenario"))] = entry.at("document").dump();
    } catch (const std::exception&) {
      // The worker then refuses the job (no valid scenario): it fails with a clear error.
    }
  }
  return out;
}

}  // namespace rlpos
