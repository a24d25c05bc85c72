#include "coordinator/web/api_request.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "common/metrics/eval_metrics.h"
#include "coordinator/web/api_error.h"

namespace rlpos::web {
namespace {

std::vector<std::string> SplitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  for (std::size_t i = 1; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      parts.push_back(part);
      part.clear();
    } else {
      part += path[i];
    }
  }
  return parts;
}

// The artifact id: 1-18 digits, not starting with 0.
std::int64_t ParseArtifactId(const std::string& text) {
  if (text.empty() || text.size() > 18 || text[0] == '0' ||
      text.find_first_not_of("0123456789") != std::string::npos)
    throw ApiError(400, "artifact id: expected a positive integer");
  return std::stoll(text);
}

bool IsMetricKey(const std::string& key) {
  for (const auto& def : EvalMetricTable<double>()) {
    if (key == def.key)
      return true;
  }
  return false;
}

// Checks the parameters against those the endpoint takes, and copies them into `request`.
void ReadQuery(const QueryParams& query, const std::set<std::string>& allowed,
               ApiRequest& request) {
  if (query.size() > kMaxQueryParams)
    throw ApiError(400, "too many query parameters");
  std::set<std::string> seen;
  for (const auto& [name, value] : query) {
    if (!allowed.count(name))
      throw ApiError(400, "unknown query parameter \"" + name.substr(0, 32) + "\"");
    if (!seen.insert(name).second)
      throw ApiError(400, "query parameter \"" + name + "\" given twice");
    if (value.size() > kMaxQueryValue)
      throw ApiError(400, "query parameter \"" + name + "\" is too long");
    if (name == "metric") {
      if (!IsMetricKey(value))
        throw ApiError(400, "metric: not a metric (see rlpos-sim describe metrics)");
      request.metric = value;
    } else if (name == "kind") {
      if (value != "ccdf" && value != "cdf")
        throw ApiError(400, "kind: expected ccdf or cdf");
      request.kind = value;
    } else if (name == "scenario") {
      if (!IsScenarioName(value))
        throw ApiError(400, "scenario: not a scenario name");
      request.scenario = value;
    }
  }
}

ApiRequest ParseCampaignRequest(const std::vector<std::string>& parts, const QueryParams& query) {
  ApiRequest request;
  if (!IsCampaignId(parts[2]))
    throw ApiError(400, "campaign id: expected 12 lowercase hex digits");
  request.campaign_id = parts[2];
  if (parts.size() == 3) {
    request.endpoint = Endpoint::kCampaign;
    ReadQuery(query, {}, request);
  } else if (parts.size() == 4 && parts[3] == "distributions") {
    request.endpoint = Endpoint::kDistributions;
    request.metric = "aggregate_throughput_mbps";
    ReadQuery(query, {"metric", "kind", "scenario"}, request);
  } else if (parts.size() == 4 && parts[3] == "learning-curves") {
    request.endpoint = Endpoint::kLearningCurves;
    ReadQuery(query, {"scenario"}, request);
  } else if (parts.size() == 4 && parts[3] == "maps") {
    request.endpoint = Endpoint::kMaps;
    ReadQuery(query, {}, request);
  } else {
    throw ApiError(404, "no such endpoint");
  }
  return request;
}

}  // namespace

bool IsCampaignId(const std::string& text) {
  return text.size() == 12 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

bool IsScenarioName(const std::string& text) {
  return !text.empty() && text.size() <= 64 && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
           c == ' ';
  });
}

ApiRequest ParseApiRequest(const std::string& path, const QueryParams& query) {
  ApiRequest request;
  if (path == "/" || path == "/index.html") {
    ReadQuery(query, {"token"}, request);
    return request;
  }
  if (path.empty() || path[0] != '/')
    throw ApiError(400, "the path must start with /");
  const auto parts = SplitPath(path);
  if (parts.size() < 2 || parts[0] != "api")
    throw ApiError(404, "no such page (the page is /, its data under /api/)");
  if (parts[1] == "campaigns" && parts.size() == 2) {
    request.endpoint = Endpoint::kCampaigns;
    ReadQuery(query, {}, request);
    return request;
  }
  if (parts[1] == "campaigns" && parts.size() >= 3)
    return ParseCampaignRequest(parts, query);
  if (parts[1] == "artifacts" && parts.size() == 3) {
    request.endpoint = Endpoint::kArtifact;
    request.artifact_id = ParseArtifactId(parts[2]);
    ReadQuery(query, {}, request);
    return request;
  }
  throw ApiError(404, "no such endpoint");
}

}  // namespace rlpos::web
