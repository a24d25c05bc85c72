#pragma once
// The campaign list and one campaign as the page shows them (JSON), from the store's readers
// and the reporting layer: the same numbers as `rlpos-campaign status` and `results`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/store/results_reader.h"
#include "coordinator/reporting/campaign_summary.h"

namespace rlpos::web {

// Lists are cut at these lengths (the response says how many there were).
constexpr std::size_t kMaxCampaigns = 500;
constexpr std::size_t kMaxListedJobs = 200;
constexpr std::size_t kMaxListedWorkers = 100;
constexpr std::size_t kMaxListedArtifacts = 1000;
constexpr std::size_t kMaxErrorText = 500;
constexpr std::size_t kMaxListedOptimalityRuns = 1000;

// {"campaigns": [{id, name, state, total, done, jobs: {pending, ...}, eta_s}], "truncated"}.
nlohmann::json CampaignListJson(ResultsReader& store, double now);

// Progress, workers, ETA, running and failed jobs, the summary, per-UAV and optimality tables,
// the artifacts. Throws StoreError for an unknown campaign.
nlohmann::json CampaignDetailJson(ResultsReader& store, const std::string& campaign_id, double now);

// The report's optimality section (coordinator/reporting/optimality.h): {"summary": per
// algorithm (named policy, positioner) and UAV count, median, P10, worst and share >= 0.95 of the
// placement's reward over the oracle's, and the median seconds per placement; "runs": each
// placement with both rewards, the ratio and its seconds (the first kMaxListedOptimalityRuns);
// "runs_total"; "cdf": the ratio's CDF per group, [{algorithm, uavs, x, p}], each curve thinned
// to kMaxCurvePoints}. All empty when no scenario has oracle rewards.
nlohmann::json OptimalityJson(ResultsReader& store, const std::string& campaign_id);

}  // namespace rlpos::web
