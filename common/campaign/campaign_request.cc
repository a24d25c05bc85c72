#include "common/campaign/campaign_request.h"

#include <map>
#include <stdexcept>

#include "common/campaign/campaign_spec.h"
#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "common/wire/json_text.h"
#include "common/wire/limits.h"

namespace rlpos {

CampaignPlan PlanSubmittedCampaign(const std::string& campaign_json,
                                   const std::vector<SubmittedScenario>& scenarios,
                                   const SubmitLimits& limits) {
  return PlanSubmittedCampaign(campaign_json, scenarios, {}, limits);
}

CampaignPlan PlanSubmittedCampaign(const std::string& campaign_json,
                                   const std::vector<SubmittedScenario>& scenarios,
                                   const std::vector<SubmittedPolicy>& policies,
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
  if (policies.size() > kMaxCampaignPolicies) {
    throw std::invalid_argument("the campaign sends " + std::to_string(policies.size()) +
                                " policies, more than the limit of " +
                                std::to_string(kMaxCampaignPolicies));
  }
  std::map<std::string, PolicyBundle> bundles;
  for (const auto& p : policies) {
    if (bundles.count(p.folder))
      throw std::invalid_argument("policy \"" + p.folder + "\" is sent twice");
    try {
      bundles[p.folder] = MakePolicyBundle(p.files);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("policy \"" + p.folder + "\": " + e.what());
    }
  }
  CampaignSpec spec;
  try {
    spec = ParseCampaign(campaign, SentScenarioSource(documents), SentPolicySource(bundles));
  } catch (const ConfigError& e) {
    throw std::invalid_argument("campaign: " + e.describe());
  }
  // Counted, never expanded here: the store makes the jobs one at a time.
  CampaignPlan plan = PlanCampaign(std::move(spec));
  if (plan.JobCount() > limits.max_jobs) {
    throw std::invalid_argument("the campaign has " + std::to_string(plan.JobCount()) +
                                " jobs, more than the coordinator's limit of " +
                                std::to_string(limits.max_jobs));
  }
  return plan;
}

CampaignSubmission ReadCampaignSubmission(const std::string& campaign_file) {
  CampaignSubmission out;
  const nlohmann::json document = ReadJsonFile(campaign_file);
  const CampaignSpec spec = ReadCampaignFile(campaign_file);
  out.campaign = PlanCampaign(spec);
  out.campaign_json = document.dump();
  std::map<std::string, bool> sent;
  for (const auto& s : spec.scenarios) {
    if (sent[s.file])
      continue;
    sent[s.file] = true;
    out.scenarios.push_back({s.file, s.document.dump()});
  }
  std::map<std::string, bool> packed;
  for (const auto& p : spec.policies) {
    if (!packed[p.folder])
      out.policies.push_back({p.folder, p.bundle.files});
    packed[p.folder] = true;
  }
  return out;
}

}  // namespace rlpos
