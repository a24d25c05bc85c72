// The agents' hyperparameter declarations drive the parser: every declared key is accepted
// through --set and comes back from ToJson, and values beyond its declared range are refused
// naming its JSON path. The docs page is the declarations' rendering.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <type_traits>

#include "common/scenario/settings_docs.h"
#include "common/scenario/scenario_parser.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

// A value inside the declared range that is not the default.
json ValidValue(const SettingRow& row) {
  const json fallback = json::parse(row.default_value);
  const NumberRange& r = row.bounds;
  if (row.type == "boolean")
    return !fallback.get<bool>();
  if (row.type == "integer") {
    const long long d = fallback.get<long long>();
    return d + 1 <= static_cast<long long>(r.max) ? d + 1 : d - 1;
  }
  const double d = fallback.is_null() ? r.min : fallback.get<double>();
  if (r.max >= 1e300)
    return d + 1.0;
  return d < r.max ? (d + r.max) / 2 : (d + r.min) / 2;
}

// Values just beyond the declared range (none for booleans, "above" only when bounded).
std::vector<json> OutOfRangeValues(const SettingRow& row) {
  if (row.type == "boolean")
    return {"yes"};
  const NumberRange& r = row.bounds;
  std::vector<json> out;
  if (row.type == "integer") {
    out.push_back(static_cast<long long>(r.min) - 1);
    if (r.max < 1e300)
      out.push_back(static_cast<long long>(r.max) + 1);
  } else {
    out.push_back(r.min_exclusive ? r.min : r.min - 1.0);
    if (r.max < 1e300)
      out.push_back(r.max + 1.0);
  }
  return out;
}

TEST(Hyperparameters, EveryDeclaredOneIsAcceptedAndWrittenBack) {
  std::size_t count = 0;
  for (const auto& section : AllHyperparameterSections()) {
    for (const auto& row : section.rows) {
      const json value = ValidValue(row);
      json doc = ShippedScenarioDocument("b");
      // With checkpoints on, so that early_stop_checkpoints's cross-key check holds.
      ApplyOverrides(doc, {"agent.eval_interval=5", row.key + "=" + value.dump()});
      const json written = ToJson(ParseScenario(doc));
      EXPECT_EQ(written.at(json::json_pointer(Pointer(row.key))), value) << row.key;
      ++count;
    }
  }
  EXPECT_GE(count, 30u);  // the four tables, not an empty loop
}

TEST(Hyperparameters, ValuesBeyondTheDeclaredRangeAreRefused) {
  for (const auto& section : AllHyperparameterSections()) {
    for (const auto& row : section.rows) {
      for (const json& value : OutOfRangeValues(row)) {
        const std::string error =
            ErrorOf(ShippedScenarioDocument("b"), {row.key + "=" + value.dump()});
        EXPECT_EQ(error.rfind(Pointer(row.key) + ": ", 0), 0u)
            << row.key << "=" << value.dump() << " gave \"" << error << "\"";
      }
    }
  }
}

TEST(Hyperparameters, UnknownKeysSuggestADeclaredOne) {
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"agent.ppo.entropy_coeficient=0.1"}),
            "/agent/ppo/entropy_coeficient: unknown key \"entropy_coeficient\"; did you mean "
            "\"entropy_coefficient\"?");
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"agent.sac.alfa=0.1"}),
            "/agent/sac/alfa: unknown key \"alfa\"; did you mean \"alpha\"?");
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"agent.eval_intervall=2"}),
            "/agent/eval_intervall: unknown key \"eval_intervall\"; did you mean "
            "\"eval_interval\"?");
}

TEST(Hyperparameters, TheDocsPageIsTheDeclarationsRendering) {
  std::ifstream in(std::string(RLPOS_SOURCE_DIR) + "/docs/hyperparameters.md");
  ASSERT_TRUE(in) << "docs/hyperparameters.md is missing";
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_EQ(page.str(), HyperparametersMarkdown(AllHyperparameterSections()))
      << "regenerate it: rlpos-sim describe hyperparameters > docs/hyperparameters.md";
}

// The row of `key` in `section`; fails the test when there is none.
const SettingRow& RowOf(const SettingsSection& section, const std::string& key) {
  for (const auto& row : section.rows) {
    if (row.key == key)
      return row;
  }
  ADD_FAILURE() << key << " is not in " << section.section;
  static const SettingRow none{};
  return none;
}

TEST(Hyperparameters, TheSharedKeysShowEachAlgorithmsOwnDefaults) {
  const auto ppo = HyperparameterSectionsFor("ppo");
  ASSERT_EQ(ppo.at(0).section, "agent");
  EXPECT_EQ(RowOf(ppo[0], "agent.train_episodes").default_text, "4000");
  EXPECT_EQ(RowOf(ppo[0], "agent.train_episodes").default_value, "4000");
  EXPECT_EQ(RowOf(ppo[0], "agent.eval_interval").default_text, "100");
  EXPECT_EQ(RowOf(ppo[0], "agent.baseline_start_every").default_text, "4");
  const auto sac = HyperparameterSectionsFor("sac");
  EXPECT_EQ(RowOf(sac.at(0), "agent.train_episodes").default_text, "2500");
  EXPECT_EQ(RowOf(sac.at(0), "agent.train_episode_steps").default_text, "10");
  EXPECT_EQ(RowOf(HyperparameterSectionsFor("dqn").at(0), "agent.train_episodes").default_text,
            "1000");
  // The whole page: each algorithm's where they differ, one value where they agree.
  const auto all = AllHyperparameterSections();
  EXPECT_EQ(RowOf(all.at(0), "agent.train_episodes").default_text, "dqn 1000, ppo 4000, sac 2500");
  EXPECT_EQ(RowOf(all.at(0), "agent.seed").default_text, "1");
  const std::string page = HyperparametersMarkdown(ppo);
  EXPECT_NE(page.find("| `agent.train_episodes` | integer | 4000 |"), std::string::npos) << page;
}

// Whether AgentSpec has a member named like DQN's settings.
template <typename T, typename = void>
struct HasGamma : std::false_type {};
template <typename T>
struct HasGamma<T, std::void_t<decltype(std::declval<T&>().gamma)>> : std::true_type {};
template <typename T, typename = void>
struct HasReplayCapacity : std::false_type {};
template <typename T>
struct HasReplayCapacity<T, std::void_t<decltype(std::declval<T&>().replay_capacity)>>
    : std::true_type {};

TEST(Hyperparameters, NoAlgorithmReadsAnothersThroughTheAgent) {
  // PPO's and SAC's code sees the whole AgentSpec: a DQN setting there would read as its own.
  EXPECT_FALSE((std::is_base_of_v<DqnSpec, AgentSpec>));
  EXPECT_FALSE(HasGamma<AgentSpec>::value);
  EXPECT_FALSE(HasReplayCapacity<AgentSpec>::value);
  EXPECT_TRUE(HasGamma<PpoSpec>::value);
  EXPECT_TRUE(HasReplayCapacity<SacSpec>::value);
}

TEST(Hyperparameters, AnAlgorithmsTablesAreTheSharedOneAndItsOwn) {
  const auto sections = HyperparameterSectionsFor("ppo");
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].section, "agent");
  EXPECT_EQ(sections[1].section, "ppo");
  EXPECT_EQ(sections[1].rows[0].key, "agent.ppo.learning_rate");
  EXPECT_EQ(sections[1].rows[0].default_value, "0.001");
  EXPECT_EQ(sections[1].rows[0].values, "(0, 1]");
  EXPECT_EQ(AllHyperparameterSections().size(), 4u);
}

}  // namespace
}  // namespace rlpos
