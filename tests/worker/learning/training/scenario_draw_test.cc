// The scenarios a policy for any scenario trains on: drawn from a seed, within the asked
// distribution, with the training's settings, never from the held-out set's seeds.
#include "worker/learning/training/scenario_draw.h"

#include <gtest/gtest.h>

#include <set>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

Scenario DrawSettings() {
  Scenario s;
  s.env.fidelity = "analytic";
  s.env.observations = {"zone", "ues", "heights"};
  s.env.step = 10;
  s.agent.algorithm = "ppo";
  s.agent.hidden = {8};
  return s;
}

GeneratedDistribution UrbanAndOpen(CountRange uavs, std::optional<CountRange> ues = {}) {
  return {{GeneratorStyle::kUrban, GeneratorStyle::kOpen}, uavs, ues};
}

TEST(CountRange, ParsesACountOrARangeAndRefusesTheRest) {
  const CountRange one = ParseCountRange("3", 1, 6, "--uavs");
  EXPECT_EQ(one.min, 3);
  EXPECT_EQ(one.max, 3);
  const CountRange span = ParseCountRange("1-3", 1, 6, "--uavs");
  EXPECT_EQ(span.min, 1);
  EXPECT_EQ(span.max, 3);
  EXPECT_EQ(FormatCountRange(span), "1-3");
  for (const char* bad : {"", "x", "0", "7", "3-1", "1-", "-2", "1-2-3", "2.5", "+2"}) {
    try {
      ParseCountRange(bad, 1, 6, "--uavs");
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.path(), "--uavs") << bad;
    }
  }
}

TEST(ScenarioDraw, TheSameDrawIsTheSameScenarioAndTheNextIsAnother) {
  const ScenarioDraw draw(UrbanAndOpen({1, 1}), DrawSettings(), 3);
  const DrawnScenario a = draw.Training(5);
  EXPECT_EQ(ToJson(a.scenario), ToJson(draw.Training(5).scenario));
  EXPECT_NE(ToJson(a.scenario), ToJson(draw.Training(6).scenario));
  EXPECT_EQ(a.generator_seed, draw.FirstTrainingSeed() + 5);
  // Another training seed draws other scenarios.
  const ScenarioDraw other(UrbanAndOpen({1, 1}), DrawSettings(), 4);
  EXPECT_NE(ToJson(a.scenario), ToJson(other.Training(5).scenario));
}

TEST(ScenarioDraw, DrawsStayInTheDistributionAndCarryTheSettings) {
  const ScenarioDraw draw(UrbanAndOpen({1, 2}, CountRange{5, 7}), DrawSettings(), 1);
  std::set<std::size_t> uav_counts;
  std::set<std::string> styles;
  for (std::uint64_t k = 0; k < 16; ++k) {
    const Scenario s = draw.Training(k).scenario;
    uav_counts.insert(s.uavs.size());
    styles.insert(s.name.substr(0, s.name.find('-', 4)));
    EXPECT_GE(s.ues.size(), 5u) << s.name;
    EXPECT_LE(s.ues.size(), 7u) << s.name;
    EXPECT_EQ(s.env.observations, DrawSettings().env.observations) << s.name;
    EXPECT_EQ(s.env.step, 10) << s.name;
    EXPECT_EQ(s.agent.hidden, std::vector<int>{8}) << s.name;
  }
  EXPECT_EQ(uav_counts, (std::set<std::size_t>{1, 2}));
  EXPECT_EQ(styles, (std::set<std::string>{"gen-urban", "gen-open"}));
}

TEST(ScenarioDraw, NeverDrawsTheScenarioSetsSeeds) {
  // scripts/generate_scenario_set.sh: train 10000-16999, held-out 90000-96999 (with the -many
  // sets of four to six UAVs).
  const ScenarioDraw draw(UrbanAndOpen({1, 1}), DrawSettings(), 0);
  EXPECT_GT(draw.FirstTrainingSeed(), 96999u);
  EXPECT_GT(kValidationSeedBase, 96999u);
  // The validation range ends before the training ranges begin.
  EXPECT_LT(kValidationSeedBase + kDrawsPerSeed, kTrainingSeedBase + 1);
  EXPECT_GE(draw.Validation(0).generator_seed, kValidationSeedBase);
  EXPECT_LT(draw.Validation(0).generator_seed, kTrainingSeedBase);
  EXPECT_THROW(ScenarioDraw(UrbanAndOpen({1, 1}), DrawSettings(), kMaxTrainingSeed + 1),
               ConfigError);
}

TEST(ScenarioDraw, AUsersSetIsDrawnFromWithTheSettings) {
  Scenario a = DrawSettings(), b = DrawSettings();
  a.name = "a";
  b.name = "b";
  a.env.step = 5;  // replaced by the settings'
  const ScenarioDraw draw({a, b}, {"a.json", "b.json"}, DrawSettings(), 2);
  std::set<std::string> seen;
  for (std::uint64_t k = 0; k < 16; ++k) {
    const DrawnScenario d = draw.Training(k);
    seen.insert(d.origin);
    EXPECT_EQ(d.scenario.env.step, 10);
  }
  EXPECT_EQ(seen, (std::set<std::string>{"a.json", "b.json"}));
  EXPECT_EQ(draw.Validation(3).origin, "b.json");
  EXPECT_THROW(ScenarioDraw({}, {}, DrawSettings(), 2), ConfigError);
}

}  // namespace
}  // namespace rlpos
