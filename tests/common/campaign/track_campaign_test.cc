// A campaign's track section: parsed with every setting checked against each scenario, expanded
// into one track job per scenario, positioner and RngRun, and each job an order a worker takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "common/wire/job_order.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;
using testing::SourcePath;

// Scenario B, decisions every second, RngRuns 1 and 2, track runs only.
json TrackCampaign() {
  return {
      {"name", "t"},
      {"scenarios",
       {{{"file", SourcePath("campaigns/scenarios/b.json")},
         {"set", {"env.decision_interval=1"}}}}},
      {"rng_runs", {1, 2}},
      {"positioners", json::array()},
      {"track",
       {{"positioners", {"oracle-track", "centroid"}}, {"duration", 10}, {"fidelity", "packet"}}}};
}

std::string ErrorOf(const json& document) {
  try {
    ParseCampaign(document, "/");
  } catch (const ConfigError& e) {
    return e.describe();
  }
  return "accepted";
}

TEST(TrackCampaign, OneJobPerScenarioPositionerAndRunThatAWorkerTakes) {
  const CampaignPlan plan = PlanCampaign(ParseCampaign(TrackCampaign(), "/"));
  EXPECT_EQ(plan.parsed.track.positioners, (std::vector<std::string>{"centroid", "oracle-track"}));
  std::vector<std::string> keys;
  std::ifstream in(SourcePath("campaigns/scenarios/b.json"));
  const std::string document(std::istreambuf_iterator<char>(in), {});
  plan.ForEachJob([&](Job&& job) {
    keys.push_back(job.key);
    const JobParams& p = job.params;
    EXPECT_EQ(p.kind, JobKind::kTrack) << job.key;
    EXPECT_EQ(job.label, p.positioner) << job.key;
    EXPECT_EQ(job.depends_on, "") << job.key;
    EXPECT_EQ(p.fidelity, "packet");
    EXPECT_EQ(p.duration_s, 10.0);
    JobOrder order;
    order.job_id = job.id;
    order.campaign_id = plan.id;
    order.timeout_s = 600;
    order.params = p;
    order.scenario_document = document;
    EXPECT_NO_THROW(CheckJobOrder(order, 3600)) << job.key;
  });
  EXPECT_EQ(keys,
            (std::vector<std::string>{"track/B/centroid/run1", "track/B/centroid/run2",
                                      "track/B/oracle-track/run1", "track/B/oracle-track/run2"}));
  EXPECT_EQ(plan.JobCount(), keys.size());
}

TEST(TrackCampaign, ACampaignWithoutOneKeepsItsId) {
  json plain = TrackCampaign();
  plain.erase("track");
  plain.erase("positioners");
  EXPECT_FALSE(ToJson(ParseCampaign(plain, "/")).contains("track"));
  const json with = ToJson(ParseCampaign(TrackCampaign(), "/"));
  EXPECT_EQ(with["track"], json({{"positioners", {"centroid", "oracle-track"}},
                                 {"duration", 10.0},
                                 {"fidelity", "packet"}}));
}

TEST(TrackCampaign, ATrackOrderHasWhatTrackNeeds) {
  const CampaignPlan plan = PlanCampaign(ParseCampaign(TrackCampaign(), "/"));
  std::ifstream in(SourcePath("campaigns/scenarios/b.json"));
  JobOrder order;
  order.campaign_id = plan.id;
  order.timeout_s = 600;
  order.scenario_document.assign(std::istreambuf_iterator<char>(in), {});
  plan.ForEachJob([&](Job&& job) {
    if (order.job_id.empty()) {
      order.job_id = job.id;
      order.params = job.params;
    }
  });
  const auto error = [](JobOrder o) -> std::string {
    try {
      CheckJobOrder(o, 3600);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(error(order), "accepted");
  JobOrder bad = order;
  bad.params.positioner = "offsets";
  EXPECT_EQ(error(bad).rfind("positioner: must be ", 0), 0u) << error(bad);
  bad = order;
  bad.params.rng_run.reset();
  EXPECT_EQ(error(bad), "rng_run: a track job needs one in 1..4294967295");
  bad = order;
  bad.params.duration_s.reset();
  EXPECT_EQ(error(bad), "duration_s: a track job needs one");
  bad = order;
  bad.params.fidelity = "exact";
  EXPECT_EQ(error(bad).rfind("fidelity: must be ", 0), 0u) << error(bad);
  bad = order;
  bad.placement = Placement{{50, 35, 10}};
  EXPECT_EQ(error(bad), "positions: only an eval job has them");
}

TEST(TrackCampaign, BadSectionsAreOneLineErrorsWithTheirPath) {
  const auto edited = [](const std::function<void(json&)>& edit) {
    json d = TrackCampaign();
    edit(d);
    return ErrorOf(d);
  };
  EXPECT_EQ(edited([](json& d) { d["track"]["positioners"] = {"rl"}; }),
            "/track/positioners/0: rl in a track section flies a policy for any scenario: "
            "{\"rl\": {\"policy\": \"FOLDER\"}}");
  EXPECT_EQ(edited([](json& d) { d["track"]["positioners"] = {"oracle-trak"}; }),
            "/track/positioners/0: unknown track positioner \"oracle-trak\" (one of: baseline, "
            "centroid, oracle, oracle-track, centroid-track); did you mean \"oracle-track\"?");
  EXPECT_EQ(edited([](json& d) { d["track"].erase("duration"); }),
            "/track/duration: is required (s of each run)");
  EXPECT_EQ(edited([](json& d) {
              d["track"]["fidelty"] = "packet";
            }).rfind("/track/fidelty: unknown key", 0),
            0u);
  EXPECT_EQ(edited([](json& d) { d["track"]["duration"] = 601; }),
            "/track/duration: makes 601 intervals in scenario \"B\" (/scenarios/0, "
            "env.decision_interval 1 s), more than 600; lengthen its env.decision_interval "
            "(\"set\") or shorten the runs");
  EXPECT_EQ(edited([](json& d) { d["track"]["duration"] = 0.5; }),
            "/track/duration: is shorter than one interval of scenario \"B\" (/scenarios/0, "
            "env.decision_interval 1 s)");
  EXPECT_EQ(edited([](json& d) { d["track"]["duration"] = 1; }),
            "/track/duration: leaves no interval after simulation.warmup (1 s) in scenario "
            "\"B\" (/scenarios/0, env.decision_interval 1 s)");
  EXPECT_EQ(edited([](json& d) { d.erase("track"); }),
            "/positioners: expected a non-empty array, got an empty array");
}

json Generalist() {
  return {{"rl", {{"policy", SourcePath("policies/generalist-1uav")}, {"name", "g"}}}};
}

std::vector<std::string> KeysOf(const CampaignPlan& plan) {
  std::vector<std::string> keys;
  plan.ForEachJob([&](Job&& job) { keys.push_back(job.key); });
  return keys;
}

TEST(TrackCampaign, APolicyForAnyScenarioFliesInTrackRuns) {
  json doc = TrackCampaign();
  doc["track"]["positioners"] = {"centroid", Generalist()};
  const CampaignPlan plan = PlanCampaign(ParseCampaign(doc, "/"));
  ASSERT_EQ(plan.parsed.policies.size(), 1u);
  const CampaignPolicy& g = plan.parsed.policies.front();
  EXPECT_TRUE(g.tracked);
  EXPECT_FALSE(g.placed) << "listed in the track section only: no position job";
  plan.ForEachJob([&](Job&& job) {
    if (job.label != "rl+g")
      return;
    EXPECT_EQ(job.params.positioner, "rl");
    EXPECT_EQ(job.params.policy_sha256, g.bundle.sha256);
  });
  EXPECT_EQ(KeysOf(plan),
            (std::vector<std::string>{"track/B/centroid/run1", "track/B/centroid/run2",
                                      "track/B/rl+g/run1", "track/B/rl+g/run2"}));
  EXPECT_EQ(plan.JobCount(), 4u);
  const json policy = ToJson(plan.parsed)["policies"][0];
  EXPECT_EQ(policy["track"], true);
  EXPECT_EQ(policy["placed"], false);
  // The track run may set its own decision interval; a placement flies with the policy's.
  doc["positioners"] = {Generalist()};
  EXPECT_EQ(ErrorOf(doc).rfind("/positioners/0/rl/policy: policy ", 0), 0u) << ErrorOf(doc);
  doc["scenarios"][0]["set"] = json::array();
  const CampaignPlan both = PlanCampaign(ParseCampaign(doc, "/"));
  ASSERT_EQ(both.parsed.policies.size(), 1u) << "one folder in both lists is one policy";
  EXPECT_TRUE(both.parsed.policies.front().placed && both.parsed.policies.front().tracked);
  const std::vector<std::string> keys = KeysOf(both);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "position/B/rl+g"), 1);
  EXPECT_EQ(std::count(keys.begin(), keys.end(), "track/B/rl+g/run2"), 1);
  EXPECT_EQ(both.JobCount(), keys.size());
}

}  // namespace
}  // namespace rlpos
