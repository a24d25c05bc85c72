// The campaign page's API as function calls over a real campaign's database: what each endpoint
// answers, the access checks, the artifacts' paths, the errors (one-line JSON), and the database
// left byte for byte as it was.
#include "coordinator/web/api_router.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/store/artifact_files.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/distribution_curves.h"
#include "coordinator/web/page_assets.h"
#include "tests/coordinator/web/web_fixture.h"

namespace rlpos::web {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

class ApiRouterTest : public ::testing::Test {
 protected:
  ApiRouterTest() {
    context_.db_file = db_.file();
    context_.clock = [] { return 2e9; };
  }

  ApiResponse Get(const std::string& path, const QueryParams& query = {}) {
    HttpRequestView request;
    request.method = "GET";
    request.path = path;
    request.query = query;
    request.host = "127.0.0.1:8787";
    request.authorization = authorization_;
    return Respond(request, context_);
  }

  json GetJson(const std::string& path, const QueryParams& query = {}) {
    const ApiResponse response = Get(path, query);
    EXPECT_EQ(response.status, 200) << path << ": " << response.body;
    EXPECT_EQ(response.content_type, "application/json");
    return json::parse(response.body);
  }

  // The status, after checking that the body is one line of {"error": "..."}.
  int ErrorStatus(const ApiResponse& response) {
    EXPECT_EQ(response.content_type, "application/json");
    EXPECT_EQ(response.body.find('\n'), response.body.size() - 1) << response.body;
    const json body = json::parse(response.body);
    EXPECT_TRUE(body.is_object() && body.size() == 1 && body["error"].is_string()) << response.body;
    return response.status;
  }

  std::string Campaign() const { return "/api/campaigns/" + db_.id(); }

  ResultsReader& Reader() {
    StoreOptions options;
    options.read_only = true;
    reader_db_ = std::make_unique<StoreDb>(db_.file(), options);
    reader_ = std::make_unique<ResultsReader>(*reader_db_);
    return *reader_;
  }

  testing::CampaignDb db_;
  ServeContext context_;
  std::string authorization_;
  std::unique_ptr<StoreDb> reader_db_;
  std::unique_ptr<ResultsReader> reader_;
};

TEST_F(ApiRouterTest, ListsCampaignsWithTheirProgress) {
  const json list = GetJson("/api/campaigns");
  ASSERT_EQ(list["campaigns"].size(), 1u);
  const json& c = list["campaigns"][0];
  EXPECT_EQ(c["id"], db_.id());
  EXPECT_EQ(c["name"], "mini");
  EXPECT_EQ(c["total"], 44);
  // 5 producers, 8 evals succeeded; the failed eval is done too.
  EXPECT_EQ(c["jobs"]["succeeded"], 13);
  EXPECT_EQ(c["jobs"]["failed"], 1);
  EXPECT_EQ(c["done"], 14);
  EXPECT_EQ(c["settled"], false);
  EXPECT_TRUE(c["eta_s"].is_number());
}

TEST_F(ApiRouterTest, ShowsOneCampaignWithItsTables) {
  const json c = GetJson(Campaign());
  EXPECT_EQ(c["failed_total"], 1);
  ASSERT_EQ(c["failed"].size(), 1u);
  EXPECT_EQ(c["failed"][0]["key"], "eval/B/centroid/run2");
  EXPECT_EQ(c["failed"][0]["error"], "exit code 1: \"boom\"\nsecond line");
  EXPECT_EQ(c["summary"].size(), SummarizeCampaign(Reader(), db_.id()).size());
  EXPECT_EQ(c["scenarios"], json({"B", "C"}));
  EXPECT_EQ(c["positioners"], json({"baseline", "centroid", "oracle", "rl"}));
  // rl in B: reward 0.72 against the oracle's 0.9, then the oracle's own; C has no rl, and B's
  // centroid no reward.
  const json& optimality = c["optimality"];
  ASSERT_EQ(optimality["runs"].size(), 2u);
  EXPECT_EQ(optimality["runs_total"], 2);
  EXPECT_EQ(optimality["runs"][0]["scenario"], "B");
  EXPECT_EQ(optimality["runs"][0]["train_seed"], 1);
  EXPECT_DOUBLE_EQ(optimality["runs"][0]["ratio"].get<double>(), 0.8);
  EXPECT_TRUE(optimality["runs"][0]["placement_s"].is_number());
  EXPECT_EQ(optimality["runs"][1]["label"], "oracle");
  ASSERT_EQ(optimality["summary"].size(), 2u);
  EXPECT_DOUBLE_EQ(optimality["summary"][0]["worst"].get<double>(), 0.8);
  EXPECT_EQ(optimality["summary"][0]["near_optimal_runs"], 0);
  EXPECT_EQ(optimality["summary"][1]["algorithm"], "oracle");
  // The ratio's CDF: rl's one step at 0.8; the oracle's own is no curve.
  ASSERT_EQ(optimality["cdf"].size(), 1u);
  ASSERT_EQ(optimality["cdf"][0]["x"].size(), 1u);
  EXPECT_DOUBLE_EQ(optimality["cdf"][0]["x"][0].get<double>(), 0.8);
  EXPECT_EQ(optimality["cdf"][0]["p"], json({1.0}));
  ASSERT_EQ(c["artifacts"].size(), 1u);
  EXPECT_EQ(c["artifacts"][0]["name"], "learning_curve.csv");
  EXPECT_FALSE(c["metrics"].empty());
  EXPECT_EQ(c["workers"]["alive"], 0);
}

TEST_F(ApiRouterTest, DistributionsAreTheReportsCurves) {
  const json d = GetJson(Campaign() + "/distributions");
  EXPECT_EQ(d["kind"], "ccdf");
  const auto expected = ThroughputCcdf(Reader().Metrics(db_.id()));
  std::size_t points = 0;
  for (const auto& curve : d["curves"])
    points += curve["x"].size();
  EXPECT_EQ(points, expected.size());
  ASSERT_EQ(d["curves"].size(), 5u);  // B: baseline, centroid, oracle, rl; C: oracle
  EXPECT_EQ(d["curves"][0]["positioner"], "baseline");
  EXPECT_EQ(d["curves"][0]["x"], json({100.0, 120.0}));
  EXPECT_EQ(d["curves"][0]["p"], json({0.5, 0.0}));
  const json c_only =
      GetJson(Campaign() + "/distributions", {{"metric", "mean_delay_ms"}, {"scenario", "C"}});
  EXPECT_EQ(c_only["kind"], "cdf");
  ASSERT_EQ(c_only["curves"].size(), 1u);
  EXPECT_EQ(c_only["curves"][0]["x"], json({3.0}));
  const json counts =
      GetJson(Campaign() + "/distributions", {{"metric", "n_los"}, {"kind", "ccdf"}});
  EXPECT_EQ(counts["curves"].size(), 5u);
}

TEST_F(ApiRouterTest, LearningCurvesFromTheTrainJobsArtifacts) {
  const json l = GetJson(Campaign() + "/learning-curves");
  ASSERT_EQ(l["curves"].size(), 1u);
  EXPECT_EQ(l["curves"][0]["scenario"], "B");
  EXPECT_EQ(l["curves"][0]["label"], "rl");
  EXPECT_EQ(l["curves"][0]["episode"], json({1, 2, 3}));  // the train phase only
  EXPECT_EQ(l["curves"][0]["reward"], json({1.5, 2.5, 3.5}));
  EXPECT_EQ(GetJson(Campaign() + "/learning-curves", {{"scenario", "C"}})["curves"].size(), 0u);
}

TEST_F(ApiRouterTest, MapsHoldGeometryAndPlacements) {
  const json m = GetJson(Campaign() + "/maps");
  ASSERT_EQ(m["scenarios"].size(), 2u);
  const json& b = m["scenarios"][0];
  EXPECT_EQ(b["name"], "B");
  EXPECT_EQ(b["venue"]["width"], 100.0);
  EXPECT_EQ(b["buildings"].size(), 5u);
  EXPECT_EQ(b["ues"].size(), 4u);
  std::vector<std::string> labels;
  for (const auto& p : b["placements"]) {
    labels.push_back(p["positioner"]);
    EXPECT_EQ(p["rng_run"], 1);
    ASSERT_EQ(p["uavs"].size(), 1u);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"baseline", "centroid", "oracle", "rl"}));
}

TEST_F(ApiRouterTest, ArtifactsAreServedByIdFromInsideTheirFolder) {
  const std::int64_t id = GetJson(Campaign())["artifacts"][0]["id"];
  const ApiResponse file = Get("/api/artifacts/" + std::to_string(id));
  ASSERT_EQ(file.status, 200) << file.body;
  EXPECT_EQ(file.download_name, "learning_curve.csv");
  const fs::path root = fs::canonical(ArtifactsDirOf(db_.file()));
  EXPECT_EQ(file.file, (root / db_.id() / "train/B/seed1/learning_curve.csv").string());
  EXPECT_EQ(ErrorStatus(Get("/api/artifacts/" + std::to_string(id + 1))), 404);

  // A row that names a path outside the folder (planted in the database) is never served.
  const fs::path outside = fs::path(db_.file()).parent_path() / "secret.txt";
  std::ofstream(outside) << "secret";
  for (const std::string& path :
       std::vector<std::string>{"../secret.txt", outside.string(), "a/../../secret.txt", "", "."}) {
    db_.Exec("UPDATE artifacts SET path = '" + path + "' WHERE rowid = " + std::to_string(id));
    EXPECT_EQ(ErrorStatus(Get("/api/artifacts/" + std::to_string(id))), 404) << path;
  }
  // Nor through a symbolic link inside it.
  fs::create_symlink(outside, root / "link.txt");
  db_.Exec("UPDATE artifacts SET path = 'link.txt' WHERE rowid = " + std::to_string(id));
  EXPECT_EQ(ErrorStatus(Get("/api/artifacts/" + std::to_string(id))), 404);
}

TEST_F(ApiRouterTest, BadRequestsGetOneLineJsonErrors) {
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns/ffffffffffff")), 404);
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns/ffffffffffff/maps")), 404);
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns/../../etc/passwd")), 400);
  EXPECT_EQ(ErrorStatus(Get(Campaign() + "/distributions", {{"metric", "1; DROP TABLE jobs"}})),
            400);
  EXPECT_EQ(ErrorStatus(Get("/api/nothing")), 404);
  HttpRequestView post{"POST", "/api/campaigns", {}, "", "127.0.0.1:8787"};
  EXPECT_EQ(ErrorStatus(Respond(post, context_)), 405);
  ServeContext missing = context_;
  missing.db_file = db_.file() + ".missing";
  HttpRequestView list{"GET", "/api/campaigns", {}, "", "127.0.0.1:8787"};
  const ApiResponse unreadable = Respond(list, missing);
  EXPECT_EQ(ErrorStatus(unreadable), 503);
  EXPECT_EQ(unreadable.body.find(missing.db_file), std::string::npos) << "names the server's file";
}

TEST_F(ApiRouterTest, WithoutATokenOnlyLoopbackHostsAreAnswered) {
  HttpRequestView request{"GET", "/api/campaigns", {}, "", "evil.example:8787"};
  EXPECT_EQ(ErrorStatus(Respond(request, context_)), 403);
  request.host = "localhost:8787";
  EXPECT_EQ(Respond(request, context_).status, 200);
}

TEST_F(ApiRouterTest, WithATokenEveryRequestCarriesIt) {
  context_.token = "0123456789abcdef0123";
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns")), 401);
  EXPECT_EQ(ErrorStatus(Get("/")), 401);
  authorization_ = "Bearer 0123456789abcdef0124";
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns")), 401);
  authorization_ = "Bearer 0123456789abcdef0123";
  EXPECT_EQ(Get("/api/campaigns").status, 200);
  EXPECT_EQ(Get("/").status, 200);
  // The token in the query opens the page only, never the API.
  authorization_.clear();
  EXPECT_EQ(Get("/", {{"token", "0123456789abcdef0123"}}).status, 200);
  EXPECT_EQ(ErrorStatus(Get("/", {{"token", "0123456789abcdef0124"}})), 401);
  EXPECT_EQ(ErrorStatus(Get("/api/campaigns", {{"token", "0123456789abcdef0123"}})), 401);
  // Any Host will do then: the token is the check.
  HttpRequestView remote{"GET", "/api/campaigns", {}, "Bearer 0123456789abcdef0123", "10.1.2.3"};
  EXPECT_EQ(Respond(remote, context_).status, 200);
}

TEST_F(ApiRouterTest, ThePageIsOneFileWithAStrictPolicy) {
  const ApiResponse page = Get("/");
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.content_type, "text/html; charset=utf-8");
  EXPECT_NE(page.body.find("/api/campaigns"), std::string::npos);
  EXPECT_EQ(page.body.find("<script src"), std::string::npos);
  std::string body = page.body;
  const std::string svg_namespace = "http://www.w3.org/2000/svg";  // a name, never fetched
  for (auto at = body.find(svg_namespace); at != std::string::npos; at = body.find(svg_namespace))
    body.erase(at, svg_namespace.size());
  EXPECT_EQ(body.find("http://"), std::string::npos) << "nothing from the network";
  EXPECT_EQ(body.find("https://"), std::string::npos);
  ASSERT_EQ(page.headers.size(), 1u);
  EXPECT_EQ(page.headers[0].first, "Content-Security-Policy");
  EXPECT_NE(page.headers[0].second.find("script-src 'sha256-"), std::string::npos);
  EXPECT_EQ(page.headers[0].second.find("unsafe"), std::string::npos);
}

TEST_F(ApiRouterTest, RequestsLeaveTheDatabaseAsItWas) {
  const std::string before = db_.Hash();
  for (const std::string& path :
       std::vector<std::string>{std::string("/api/campaigns"), Campaign(),
                                Campaign() + "/distributions", Campaign() + "/learning-curves",
                                Campaign() + "/maps", std::string("/api/artifacts/1")}) {
    Get(path);
  }
  Get(Campaign() + "/distributions", {{"metric", "n_los'); DELETE FROM jobs; --"}});
  EXPECT_EQ(db_.Hash(), before);
}

}  // namespace
}  // namespace rlpos::web
