#pragma once
// The scenario JSON of each job, from the campaign as the store keeps it: the
// coordinator sends it with the assignment, so a worker on another machine needs no copy of the
// submitter's files.
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace rlpos {

// Scenario name (after the campaign's per-scenario overrides) -> the scenario document as read
// (the overrides travel as the job's typed overrides). Entries that do not parse are left out.
std::map<std::string, std::string> ScenarioDocumentsByName(const nlohmann::json& campaign_spec);

}  // namespace rlpos
