// The page draws a footprint building as its exact shape: the maps' JSON carries its outer ring
// and holes as [x, y] pairs (and min_height), beside its bounding box; a box's entry is unchanged.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "coordinator/web/map_views.h"
#include "coordinator/web/page_assets.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos::web {
namespace {

using nlohmann::json;
using rlpos::testing::SourcePath;

// Scenario B with its tower (a box, 45-55 x 45-55) kept and two footprint buildings north of it:
// an L, and a yard around a courtyard that stands from 3 m up.
json YardScenario() {
  std::ifstream in(SourcePath("campaigns/scenarios/b.json"));
  json document = json::parse(in);
  json tower = document["buildings"][0];
  document["name"] = "yard";
  document["buildings"] = {
      tower,
      {{"name", "ell"},
       {"footprint", {{5, 70}, {30, 70}, {30, 78}, {13, 78}, {13, 95}, {5, 95}}},
       {"height", 12}},
      {{"name", "yard"},
       {"footprint", {{60, 75}, {95, 75}, {95, 98}, {60, 98}}},
       {"holes", {{{70, 82}, {85, 82}, {85, 92}, {70, 92}}}},
       {"height", 18},
       {"min_height", 3}}};
  return document;
}

class MapFootprintsTest : public ::testing::Test {
 protected:
  json Buildings() {
    const std::string file = dir_.File("yard.json");
    std::ofstream(file) << YardScenario().dump(2);
    const json spec = {{"name", "yard-map"},
                       {"scenarios", {{{"file", file}}}},
                       {"rng_runs", {1, 1}},
                       {"positioners", {"baseline"}}};
    const ExpandedCampaign campaign = ExpandCampaign(ParseCampaign(spec, "/"));
    CoordinatorStore store(dir_.File("rlpos.db"));
    store.ledger.Submit(campaign);
    const auto maps = ScenarioMapsJson(store.reader, campaign.id);
    EXPECT_TRUE(maps.has_value());
    const json& scenario = (*maps)["scenarios"].at(0);
    EXPECT_FALSE(scenario.contains("error")) << scenario.dump();
    return scenario.at("buildings");
  }

  rlpos::testing::TempDir dir_;
};

TEST_F(MapFootprintsTest, FootprintsCarryTheirRingsAndBoxesStayBoxes) {
  const json buildings = Buildings();
  ASSERT_EQ(buildings.size(), 3u) << buildings.dump();

  const json& tower = buildings[0];
  EXPECT_EQ(tower, json({{"name", "tower"},
                         {"xmin", 45.0},
                         {"xmax", 55.0},
                         {"ymin", 45.0},
                         {"ymax", 55.0},
                         {"height", 20.0},
                         {"floors", 6}}));

  const json& ell = buildings[1];
  EXPECT_EQ(ell["name"], "ell");
  EXPECT_EQ(ell["footprint"], json({{5, 70}, {30, 70}, {30, 78}, {13, 78}, {13, 95}, {5, 95}}));
  EXPECT_EQ(ell["holes"], json::array());
  EXPECT_EQ(ell["min_height"], 0.0);
  // Its bounding box, for what knows only boxes.
  EXPECT_EQ(ell["xmin"], 5.0);
  EXPECT_EQ(ell["xmax"], 30.0);
  EXPECT_EQ(ell["ymin"], 70.0);
  EXPECT_EQ(ell["ymax"], 95.0);

  const json& yard = buildings[2];
  EXPECT_EQ(yard["footprint"], json({{60, 75}, {95, 75}, {95, 98}, {60, 98}}));
  EXPECT_EQ(yard["holes"], json({{{70, 82}, {85, 82}, {85, 92}, {70, 92}}}));
  EXPECT_EQ(yard["min_height"], 3.0);
  EXPECT_EQ(yard["height"], 18.0);
}

// The drawing lives in page/map.js, a script of its own that the policy admits by its hash too.
TEST(MapFootprintsPage, ThePageDrawsFootprintsAsEvenOddPaths) {
  const std::string& page = PageHtml();
  EXPECT_NE(page.find("function buildingShape("), std::string::npos);
  EXPECT_NE(page.find("'fill-rule': 'evenodd'"), std::string::npos);
  EXPECT_LT(page.find("function scenarioMap("), page.find("function renderCampaign("))
      << "map.js comes before app.js";
  const std::string& policy = PageContentSecurityPolicy();
  const auto from = policy.find("script-src ");
  ASSERT_NE(from, std::string::npos);
  const std::string scripts = policy.substr(from, policy.find(';', from) - from);
  int hashes = 0;
  for (auto at = scripts.find("'sha256-"); at != std::string::npos;
       at = scripts.find("'sha256-", at + 1))
    ++hashes;
  EXPECT_EQ(hashes, 2) << scripts;
}

}  // namespace
}  // namespace rlpos::web
