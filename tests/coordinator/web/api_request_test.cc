// The typed requests of the campaign page: every path and parameter shape, and the hostile ones
// (traversal, SQL, oversize, duplicates) refused before anything reads the database.
#include "coordinator/web/api_request.h"

#include <gtest/gtest.h>

#include "coordinator/web/api_error.h"

namespace rlpos::web {
namespace {

const std::string kId = "0123456789ab";

int StatusOf(const std::string& path, const QueryParams& query = {}) {
  try {
    ParseApiRequest(path, query);
    return 200;
  } catch (const ApiError& e) {
    return e.status();
  }
}

TEST(ApiRequest, ParsesEveryEndpoint) {
  EXPECT_EQ(ParseApiRequest("/", {}).endpoint, Endpoint::kPage);
  EXPECT_EQ(ParseApiRequest("/api/campaigns", {}).endpoint, Endpoint::kCampaigns);
  const auto one = ParseApiRequest("/api/campaigns/" + kId, {});
  EXPECT_EQ(one.endpoint, Endpoint::kCampaign);
  EXPECT_EQ(one.campaign_id, kId);
  const auto curves =
      ParseApiRequest("/api/campaigns/" + kId + "/distributions",
                      {{"metric", "mean_delay_ms"}, {"kind", "ccdf"}, {"scenario", "B"}});
  EXPECT_EQ(curves.endpoint, Endpoint::kDistributions);
  EXPECT_EQ(curves.metric, "mean_delay_ms");
  EXPECT_EQ(curves.kind, "ccdf");
  EXPECT_EQ(curves.scenario, "B");
  EXPECT_EQ(ParseApiRequest("/api/campaigns/" + kId + "/distributions", {}).metric,
            "aggregate_throughput_mbps");
  EXPECT_EQ(ParseApiRequest("/api/campaigns/" + kId + "/learning-curves", {}).endpoint,
            Endpoint::kLearningCurves);
  EXPECT_EQ(ParseApiRequest("/api/campaigns/" + kId + "/maps", {}).endpoint, Endpoint::kMaps);
  const auto artifact = ParseApiRequest("/api/artifacts/42", {});
  EXPECT_EQ(artifact.endpoint, Endpoint::kArtifact);
  EXPECT_EQ(artifact.artifact_id, 42);
}

TEST(ApiRequest, RefusesTraversalInIds) {
  // Paths arrive percent-decoded: "..%2f" is "../" here.
  for (const std::string& bad : std::vector<std::string>{
           "/api/campaigns/../../etc/passwd", "/api/campaigns/..", "/api/campaigns/../" + kId,
           "/api/campaigns/" + kId + "/../maps", "/api/campaigns/%2e%2e",
           "/api/campaigns/0123456789AB", "/api/campaigns/0123456789abc",
           "/api/campaigns/" + kId + "%00", "/api/campaigns/" + kId + "\n",
           "/api/campaigns//" + kId, "/api/artifacts/../1"}) {
    const int status = StatusOf(bad);
    EXPECT_TRUE(status == 400 || status == 404) << bad << ": " << status;
  }
  for (const std::string& bad : std::vector<std::string>{
           "/api/artifacts/0", "/api/artifacts/-1", "/api/artifacts/1e3", "/api/artifacts/01",
           "/api/artifacts/9999999999999999999999", "/api/artifacts/1.0"}) {
    EXPECT_EQ(StatusOf(bad), 400) << bad;
  }
  EXPECT_EQ(StatusOf("/api/artifacts/1/../2"), 404);
}

TEST(ApiRequest, RefusesUnknownPathsAndParameters) {
  EXPECT_EQ(StatusOf("/etc/passwd"), 404);
  EXPECT_EQ(StatusOf("/api"), 404);
  EXPECT_EQ(StatusOf("/api/"), 404);
  EXPECT_EQ(StatusOf("/api/campaigns/" + kId + "/report"), 404);
  EXPECT_EQ(StatusOf("relative"), 400);
  EXPECT_EQ(StatusOf("/api/campaigns", {{"id", "1 OR 1=1"}}), 400);
  const std::string distributions = "/api/campaigns/" + kId + "/distributions";
  EXPECT_EQ(StatusOf(distributions, {{"metric", "x'; DROP TABLE jobs; --"}}), 400);
  EXPECT_EQ(StatusOf(distributions, {{"metric", "n_los"}, {"metric", "n_ues"}}), 400);
  EXPECT_EQ(StatusOf(distributions, {{"kind", "pdf"}}), 400);
  EXPECT_EQ(StatusOf(distributions, {{"scenario", "B' OR '1'='1"}}), 400);
  EXPECT_EQ(StatusOf(distributions, {{"scenario", std::string(65, 'a')}}), 400);
  QueryParams many;
  for (int i = 0; i < 9; ++i)
    many.push_back({"metric", "n_los"});
  EXPECT_EQ(StatusOf(distributions, many), 400);
  EXPECT_EQ(StatusOf("/", {{"token", std::string(65, 'a')}}), 400);
}

TEST(ApiRequest, IdsHaveTheirFormat) {
  EXPECT_TRUE(IsCampaignId("ef9929104b53"));
  EXPECT_FALSE(IsCampaignId("ef9929104b5"));
  EXPECT_FALSE(IsCampaignId("EF9929104B53"));
  EXPECT_FALSE(IsCampaignId("ef9929104b5g"));
  EXPECT_TRUE(IsScenarioName("B-abort 2.x"));
  EXPECT_FALSE(IsScenarioName(""));
  EXPECT_FALSE(IsScenarioName("a/b"));
}

}  // namespace
}  // namespace rlpos::web
