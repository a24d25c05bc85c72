#pragma once
// The requests of the campaign page, typed: which endpoint, which campaign or artifact (by id,
// validated), which metric. Parsed from the path (already percent-decoded) and the query; any
// other shape is an ApiError 400 or 404, so nothing a client writes reaches SQL or a file path.
//   GET /                                         the page
//   GET /api/campaigns                            every campaign with its progress
//   GET /api/campaigns/ID                         one campaign: jobs, workers, ETA, tables
//   GET /api/campaigns/ID/distributions?metric=M[&kind=ccdf|cdf][&scenario=S]
//   GET /api/campaigns/ID/learning-curves[?scenario=S]
//   GET /api/campaigns/ID/maps                    scenario geometry and placements
//   GET /api/artifacts/N                          an artifact's file, by its id
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rlpos::web {

enum class Endpoint {
  kPage,
  kCampaigns,
  kCampaign,
  kDistributions,
  kLearningCurves,
  kMaps,
  kArtifact
};

struct ApiRequest {
  Endpoint endpoint = Endpoint::kPage;
  std::string campaign_id;       // 12 lowercase hex digits
  std::int64_t artifact_id = 0;  // > 0
  std::string metric;            // a key of EvalMetricTable (distributions)
  std::string kind;              // ccdf | cdf; "" for the metric's default
  std::string scenario;          // "" for every scenario
};

using QueryParams = std::vector<std::pair<std::string, std::string>>;

// Bounds of what a request may carry.
constexpr std::size_t kMaxQueryParams = 8;
constexpr std::size_t kMaxQueryValue = 64;

// Throws ApiError (404 for an unknown path, 400 for a malformed id or parameter).
ApiRequest ParseApiRequest(const std::string& path, const QueryParams& query);

// 12 lowercase hex digits (common/campaign/campaign_id.h).
bool IsCampaignId(const std::string& text);
// A scenario name as a parameter: 1-64 characters of [A-Za-z0-9_.-] and spaces.
bool IsScenarioName(const std::string& text);

}  // namespace rlpos::web
