#include "wire/campaign_request.h"

#include <map>
#include <stdexcept>

#include "campaign/campaign_spec.h"
#include "campaign/offsets.h"
#include "config/config_error.h"
#include "scenario/scenario_parser.h"
#include "wire/json_text.h"
#include "wire/limits.h"

namespace rlpos {

ExpandedCampaign ExpandSubmittedCampaign(const std::string& campaign_json,
                                         const std::vector<SubmittedScenario>& scenarios,
                                         const SubmitLimits& limits) {
  std::size_t bytes = campaign_json.size();
  for (const auto& s : scenarios)
    bytes += s.file.size() + s.document.size();
  if (bytes > limits.max_request_bytes) {
    throw std::invalid_argument("the request is " + std::to_string(bytes) +
                                " bytes, more than the coordinator's limit of " +
                                std::to_string(limits.max_request_bytes));
  }
  if (scenarios.size() > limits.max_scenarios) {
    throw std::invalid_argument("the campaign sends " + std::to_string(scenarios.size()) +
                                " scenario files, more than the coordinator's limit of " +
                                std::to_string(limits.max_scenarios));
  }
  const nlohmann::json campaign =
      wire::ParseBoundedJson(campaign_json, wire::kMaxCampaignJson, "the campaign");
  std::map<std::string, nlohmann::json> documents;
  for (const auto& s : scenarios) {
    if (documents.count(s.file)) {
      throw std::invalid_argument("scenario file \"" + s.file + "\" is sent twice");
    }
    documents[s.file] = wire::ParseBoundedJson(s.document, wire::kMaxScenarioDocument,
                                               "scenario file \"" + s.file + "\"");
  }
  CampaignSpec spec;
  try {
    spec = ParseCampaign(campaign, SentScenarioSource(documents));
  } catch (const ConfigError& e) {
    throw std::invalid_argument("campaign: " + e.describe());
  }
  // Count before expanding, as ExpandCampaign will: a hostile campaign must not make the
  // coordinator build a huge list.
  std::size_t producers = 0;  // position jobs of a scenario
  for (const char* positioner : {"baseline", "centroid", "oracle"})
    producers += spec.Uses(positioner) ? 1 : 0;
  const std::size_t trains = spec.NeedsTraining() ? spec.train.seeds.size() : 0;
  const std::size_t labels =
      producers + trains * ((spec.Uses("rl") ? 1 : 0) + (spec.Uses("offsets") ? kOffsetCount : 0));
  const std::size_t jobs_per_scenario = producers + trains + labels * spec.rng_runs.size();
  if (spec.scenarios.size() * jobs_per_scenario > limits.max_jobs) {
    throw std::invalid_argument("the campaign has " +
                                std::to_string(spec.scenarios.size() * jobs_per_scenario) +
                                " jobs, more than the coordinator's limit of " +
                                std::to_string(limits.max_jobs));
  }
  ExpandedCampaign expanded = ExpandCampaign(spec);
  if (expanded.jobs.size() > limits.max_jobs) {
    throw std::invalid_argument("the campaign has " + std::to_string(expanded.jobs.size()) +
                                " jobs, more than the coordinator's limit of " +
                                std::to_string(limits.max_jobs));
  }
  return expanded;
}

CampaignSubmission ReadCampaignSubmission(const std::string& campaign_file) {
  CampaignSubmission out;
  const nlohmann::json document = ReadJsonFile(campaign_file);
  const CampaignSpec spec = ReadCampaignFile(campaign_file);
  out.campaign = ExpandCampaign(spec);
  out.campaign_json = document.dump();
  std::map<std::string, bool> sent;
  for (const auto& s : spec.scenarios) {
    if (sent[s.file])
      continue;
    sent[s.file] = true;
    out.scenarios.push_back({s.file, s.document.dump()});
  }
  return out;
}

}  // namespace rlpos
