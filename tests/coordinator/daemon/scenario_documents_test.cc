#include "coordinator/daemon/scenario_documents.h"

#include <gtest/gtest.h>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/wire/job_order.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;

json Entry(const json& document, const json& set) {
  return {{"file", "scenarios/x.json"}, {"set", set}, {"document", document}};
}

TEST(ScenarioDocuments, ShippedCampaignGivesEachScenarioItsDocument) {
  const json spec = ToJson(testing::MiniSpec());
  const auto documents = ScenarioDocumentsByName(spec);
  ASSERT_EQ(documents.size(), 2u);
  ASSERT_EQ(documents.count("B"), 1u);
  ASSERT_EQ(documents.count("C"), 1u);
  EXPECT_EQ(json::parse(documents.at("B")), spec["scenarios"][0]["document"]);
  EXPECT_EQ(json::parse(documents.at("C")), spec["scenarios"][1]["document"]);
  EXPECT_EQ(json::parse(documents.at("B"))["name"], "B");
}

TEST(ScenarioDocuments, NameAfterOverridesDocumentAsRead) {
  const json doc_b = {{"name", "B"}, {"wifi", {{"mode", "infra"}}}};
  const json spec = {{"scenarios",
                      {Entry(doc_b, {"name=B-adhoc", "wifi.mode=adhoc"}),
                       Entry(doc_b, json::array()), Entry({{"ues", json::array()}}, json::array()),
                       Entry({{"name", "D"}}, json::array({"/name=E"}))}}};
  const auto documents = ScenarioDocumentsByName(spec);
  ASSERT_EQ(documents.size(), 4u);
  // The overrides rename it, but the document travels as read: the overrides travel as the
  // job's typed overrides.
  ASSERT_EQ(documents.count("B-adhoc"), 1u);
  EXPECT_EQ(json::parse(documents.at("B-adhoc")), doc_b);
  ASSERT_EQ(documents.count("B"), 1u);
  EXPECT_EQ(json::parse(documents.at("B")), doc_b);
  // No name: the parser's default.
  ASSERT_EQ(documents.count("scenario"), 1u);
  EXPECT_EQ(json::parse(documents.at("scenario")), (json{{"ues", json::array()}}));
  // JSON-pointer override.
  ASSERT_EQ(documents.count("E"), 1u);
  EXPECT_EQ(documents.count("D"), 0u);
}

// Every job of the shipped campaigns, ordered as the coordinator orders it (the document by the
// job's scenario name, its typed fields, its timeout), passes the worker's check, and runs the
// scenario the campaign validated: the campaign entry's overrides applied to the document.
TEST(ScenarioDocuments, EveryShippedJobPassesTheWorkersCheck) {
  for (const std::string file : {"campaigns/mini.json", "campaigns/paper.json"}) {
    SCOPED_TRACE(file);
    const CampaignSpec spec = ReadCampaignFile(testing::SourcePath(file));
    const ExpandedCampaign campaign = ExpandCampaign(spec);
    const auto documents = ScenarioDocumentsByName(json::parse(campaign.spec_json));
    ASSERT_EQ(documents.size(), spec.scenarios.size());
    std::map<std::string, int> checked;
    for (const auto& job : campaign.jobs) {
      SCOPED_TRACE(job.key);
      JobOrder order;
      order.job_id = job.id;
      order.campaign_id = campaign.id;
      order.timeout_s = campaign.job_timeout_s;
      order.params = job.params;
      order.scenario_document = documents.at(job.params.scenario);
      if (job.params.kind == JobKind::kEval)
        order.placement = Placement{{1, 1, 5}};  // a corner of the venue, outside every building
      CheckedOrder c;
      ASSERT_NO_THROW(c = CheckJobOrder(order, campaign.job_timeout_s));
      EXPECT_EQ(c.parsed.name, job.params.scenario);
      if (job.params.kind == JobKind::kEval) {
        EXPECT_EQ(c.scenario["simulation"]["run"], *job.params.rng_run);
      }
      if (spec.eval.duration) {
        EXPECT_EQ(c.parsed.simulation.duration, *spec.eval.duration);
      }
      ++checked[ToString(job.params.kind)];
    }
    EXPECT_EQ(checked["train"] + checked["position"] + checked["eval"],
              static_cast<int>(campaign.jobs.size()));
  }
}

TEST(ScenarioDocuments, MalformedEntriesAreSkipped) {
  const json spec = {{"scenarios",
                      {
                          "not an object",
                          {{"file", "a.json"}, {"set", json::array()}},         // no document
                          {{"file", "a.json"}, {"document", {{"name", "A"}}}},  // no set
                          Entry({{"name", "F"}}, "name=G"),                     // set not a list
                          Entry({{"name", "H"}}, {"no-equals-sign"}),           // bad override
                          Entry({{"name", "I"}}, {1, 2}),                       // not strings
                          Entry(json::array({1, 2}), json::array()),            // not an object
                          Entry({{"name", 5}}, json::array()),                  // name not text
                          Entry({{"name", "ok"}}, json::array()),
                      }}};
  const auto documents = ScenarioDocumentsByName(spec);
  ASSERT_EQ(documents.size(), 1u);
  EXPECT_EQ(documents.begin()->first, "ok");
  EXPECT_EQ(json::parse(documents.begin()->second), (json{{"name", "ok"}}));
}

TEST(ScenarioDocuments, SpecWithoutScenarioListGivesNothing) {
  EXPECT_TRUE(ScenarioDocumentsByName(json::object()).empty());
  EXPECT_TRUE(ScenarioDocumentsByName({{"scenarios", "b.json"}}).empty());
  EXPECT_TRUE(ScenarioDocumentsByName({{"scenarios", json::array()}}).empty());
}

}  // namespace
}  // namespace rlpos
