#include "coordinator/daemon/scenario_documents.h"

#include <stdexcept>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {

std::map<std::string, std::string> ScenarioDocumentsByName(const nlohmann::json& campaign_spec) {
  std::map<std::string, std::string> out;
  if (!campaign_spec.contains("scenarios") || !campaign_spec["scenarios"].is_array())
    return out;
  for (const auto& entry : campaign_spec["scenarios"]) {
    try {
      nlohmann::json document = entry.at("document");
      nlohmann::json named = document;
      ApplyOverrides(named, entry.at("set").get<std::vector<std::string>>());
      // The parser's default name when the document has none.
      out[named.value("name", std::string("scenario"))] = document.dump();
    } catch (const std::exception&) {
      // The worker then refuses the job (no valid scenario): it fails with a clear error.
    }
  }
  return out;
}

}  // namespace rlpos
