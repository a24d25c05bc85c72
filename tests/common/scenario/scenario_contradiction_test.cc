#include "common/scenario/scenario_contradiction.h"

#include <gtest/gtest.h>

#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

using nlohmann::json;

json Document(const std::string& name) {
  return ReadJsonFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/" + name + ".json");
}

Scenario Trained(const std::vector<std::string>& overrides) {
  json d = Document("b");
  ApplyOverrides(d, overrides);
  return ParseScenario(d);
}

TEST(ScenarioContradiction, WhatADocumentLeavesUnstatedIsThePolicys) {
  const Scenario trained = Trained({"env.step=10", "env.reward.w1=0.5"});
  EXPECT_FALSE(FirstContradiction(trained, Document("b")));
  // Its own full document, and a restatement with "uavs" for "uav".
  EXPECT_FALSE(FirstContradiction(trained, ToJson(trained)));
  json listed = Document("b");
  listed["uavs"] = json::array({listed["uav"]});
  listed.erase("uav");
  EXPECT_FALSE(FirstContradiction(trained, listed));
}

TEST(ScenarioContradiction, EvaluationSettingsAndTheAgentAreTheDocumentsOwn) {
  json d = Document("b");
  ApplyOverrides(d,
                 {"name=B2", "simulation.run=9", "simulation.duration=3", "env.fidelity=analytic",
                  "agent.hidden=[64]", "agent.train_episodes=5", "log_level=debug"});
  EXPECT_FALSE(FirstContradiction(Trained({}), d));
}

TEST(ScenarioContradiction, TheFirstFieldThatDiffersIsNamed) {
  const Scenario trained = Trained({"env.step=10"});
  json step = Document("b");
  ApplyOverrides(step, {"env.step=5"});
  const auto c = FirstContradiction(trained, step);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->path, "/env/step");
  EXPECT_EQ(c->problem, "5.0 in the scenario, 10.0 in the policy");
  // Another scenario: A has no buildings; C other demands.
  EXPECT_EQ(FirstContradiction(trained, Document("a"))->path, "/buildings");
  EXPECT_EQ(FirstContradiction(trained, Document("c"))->path, "/ues/0/demand/mcs");
  // The UAVs are what is placed: a document's default UAV is not B's.
  json no_uav = Document("b");
  ApplyOverrides(no_uav, {"uav.position=[50,50,40]"});
  const auto uav = FirstContradiction(trained, no_uav);
  ASSERT_TRUE(uav);
  EXPECT_EQ(uav->path, "/uav/position/2") << uav->problem;
  no_uav.erase("uav");
  EXPECT_EQ(FirstContradiction(trained, no_uav)->path, "/uav/position");  // inside the tower
  // Fields that do not fit with the policy's are named as the parser names them.
  json small = Document("b");
  ApplyOverrides(small, {"venue.width=40"});
  const auto venue = FirstContradiction(trained, small);
  ASSERT_TRUE(venue);
  EXPECT_NE(venue->problem.find("the scenario's fields on the policy's"), std::string::npos)
      << venue->path << ": " << venue->problem;
}

}  // namespace
}  // namespace rlpos
