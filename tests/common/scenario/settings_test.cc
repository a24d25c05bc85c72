// The scenario sections' declarations (the top level's, venue, wifi, traffic, simulation, env,
// env.reward) drive the parser: every declared key is accepted through --set and comes back from
// ToJson, a value beyond its range or outside its choices is refused naming its JSON path, and an
// unknown key suggests a declared one. `describe settings` lists every section, the agents'
// included, and every key a shipped scenario holds.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "common/scenario/default_sets.h"
#include "common/scenario/settings_docs.h"
#include "tests/common/scenario/scenario_error.h"

namespace rlpos {
namespace {

using nlohmann::json;

// The scenario's own sections: the agent's are tested by hyperparameters_test.cc.
std::vector<SettingsSection> ScenarioSections() {
  std::vector<SettingsSection> out;
  const auto agent = AllHyperparameterSections();
  for (auto& section : AllSettingsSections()) {
    bool is_agent = false;
    for (const auto& a : agent)
      is_agent = is_agent || a.section == section.section;
    if (!is_agent)
      out.push_back(section);
  }
  return out;
}

// Those whose keys --set reaches in scenario B by their docs name, with their rows of a type the
// tests below know how to vary (not the custom shapes: [x, y, z], zones). The keys of a list's
// elements ("buildings.<i>", "ues.<i>.mobility") have tests of their own
// (scenario_parser_test.cc, mobility_parser_test.cc), and the golden files pin their defaults.
std::vector<SettingsSection> SettableSections() {
  std::vector<SettingsSection> out;
  for (auto section : ScenarioSections()) {
    if (section.path.find("<i>") != std::string::npos)
      continue;
    std::vector<SettingRow> rows;
    for (const auto& row : section.rows) {
      if (row.type.find('[') == std::string::npos && row.type.find('{') == std::string::npos)
        rows.push_back(row);
    }
    section.rows = rows;
    out.push_back(section);
  }
  return out;
}

// A value other than the default that every cross-key check of scenario B accepts: where one
// applies (widths the standard has, a warm-up shorter than the run...), the table below.
json OtherValue(const SettingRow& row) {
  static const std::map<std::string, json> kAcceptable = {
      {"name", "another"},
      {"description", "another scenario"},
      {"propagation", {{"type", "ns3::FriisPropagationLossModel"}, {"attributes", json::object()}}},
      {"wifi.standard", "802.11ax"},
      {"wifi.width", 80},
      {"wifi.guard_interval", 400},
      {"wifi.noise_floor", -80.0},
      {"wifi.rate_manager",
       {{"type", "ns3::MinstrelHtWifiManager"}, {"attributes", json::object()}}},
      {"simulation.warmup", 2.0},
      {"env.height_map", 11},
      {"env.decision_interval", 0.5},
      {"env.actions", {"up", "down", "stay"}},
      {"env.observations", {"x", "y", "z", "throughput"}},
      // SAC flies a continuous space: B's DQN a discrete one.
      {"env.action_space", "discrete"},
      {"uav.name", "drone"},
      {"uav.channel", 114},
  };
  if (const auto it = kAcceptable.find(row.key); it != kAcceptable.end())
    return it->second;
  const json fallback = json::parse(row.default_value);
  if (row.type == "boolean")
    return !fallback.get<bool>();
  if (row.type == "string") {
    for (const auto& choice : row.choices) {
      if (choice != fallback.get<std::string>())
        return choice;
    }
  }
  const NumberRange& r = row.bounds;
  if (row.type == "integer") {
    const long long d = fallback.get<long long>();
    return d + 1 <= static_cast<long long>(r.max) ? d + 1 : d - 1;
  }
  const double d = fallback.get<double>();
  return r.max >= 1e300 ? d + 1.0 : (d < r.max ? (d + r.max) / 2 : (d + r.min) / 2);
}

// Values a key refuses: beyond its range, outside its choices, of another type.
std::vector<json> RefusedValues(const SettingRow& row) {
  if (row.type == "boolean")
    return {"yes"};
  if (row.type == "string")
    return row.choices.empty() ? std::vector<json>{3} : std::vector<json>{"no-such-choice", 3};
  if (row.type == "list of strings")
    return {json::array(), json::array({"no-such-choice"}), "x"};
  if (row.type == "ns-3 object")
    return {json::object(), "ns3::IdealWifiManager"};
  const NumberRange& r = row.bounds;
  std::vector<json> out{"1"};
  if (row.type == "integer") {
    out.push_back(static_cast<long long>(r.min) - 1);
    if (r.max < 1e300)
      out.push_back(static_cast<long long>(r.max) + 1);
    out.push_back(r.min + 0.5);
  } else {
    if (r.min > -1e300)
      out.push_back(r.min_exclusive ? r.min : r.min - 1.0);
    if (r.max < 1e300)
      out.push_back(r.max + 1.0);
  }
  return out;
}

TEST(Settings, EveryScenarioSectionIsDeclared) {
  std::set<std::string> names;
  for (const auto& section : ScenarioSections())
    names.insert(section.section);
  EXPECT_EQ(names, (std::set<std::string>{
                       "scenario", "venue", "building", "ue", "uav", "mobility.random_walk",
                       "mobility.random_waypoint", "mobility.gauss_markov", "mobility.crowd",
                       "wifi", "traffic", "simulation", "env", "env.reward", "agent.network"}));
}

TEST(Settings, EveryDeclaredOneIsAcceptedAndWrittenBack) {
  std::size_t count = 0;
  for (const auto& section : SettableSections()) {
    for (const auto& row : section.rows) {
      const json value = OtherValue(row);
      json doc = ShippedScenarioDocument("b");
      // Turns on the keys that are written only when set or used (env.observed_ues, ...).
      ApplyOverrides(
          doc, {"env.observations=[\"x\",\"y\",\"z\",\"ues\"]", row.key + "=" + value.dump()});
      const json written = ToJson(ParseScenario(doc));
      EXPECT_EQ(written.at(json::json_pointer(Pointer(row.key))), value) << row.key;
      ++count;
    }
  }
  EXPECT_GE(count, 30u);  // the six tables, not an empty loop
}

TEST(Settings, RefusedValuesNameTheirPath) {
  for (const auto& section : SettableSections()) {
    for (const auto& row : section.rows) {
      for (const json& value : RefusedValues(row)) {
        const std::string error =
            ErrorOf(ShippedScenarioDocument("b"), {row.key + "=" + value.dump()});
        EXPECT_EQ(error.rfind(Pointer(row.key), 0), 0u)
            << row.key << "=" << value.dump() << " gave \"" << error << "\"";
      }
    }
  }
}

TEST(Settings, AChoiceOutsideTheListNamesTheChoices) {
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"wifi.standard=\"802.11g\""}),
            "/wifi/standard: unknown value \"802.11g\" (one of: 802.11n, 802.11ac, 802.11ax); did "
            "you mean \"802.11n\"?");
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"log_level=verbose"}),
            "/log_level: unknown value \"verbose\" (one of: error, warning, info, debug)");
}

TEST(Settings, UnknownKeysSuggestADeclaredOne) {
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"wifi.tx_powr=10"}),
            "/wifi/tx_powr: unknown key \"tx_powr\"; did you mean \"tx_power\"?");
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"env.reward.w4=1"}),
            "/env/reward/w4: unknown key \"w4\"; did you mean \"w1\"?");
}

TEST(Settings, TheRewardsThirdWeightFollowsItsName) {
  const auto w3 = [](const std::vector<std::string>& overrides) {
    json doc = ShippedScenarioDocument("b");
    ApplyOverrides(doc, overrides);
    return ParseScenario(doc).env.reward.w3;
  };
  EXPECT_EQ(w3({"env.reward={\"name\": \"demand_aware\"}"}), 0.2);
  EXPECT_EQ(w3({"env.reward={\"name\": \"paper\"}"}), 0.0);
  EXPECT_EQ(w3({"env.reward={\"name\": \"demand_aware\", \"w3\": 0.5}"}), 0.5);
}

TEST(Settings, CustomShapesAndRequiredKeysInTheDocs) {
  const SettingsSection uav = SettingsSectionNamed("uav");
  EXPECT_EQ(uav.rows.at(1).key, "uav.position");
  EXPECT_EQ(uav.rows.at(1).type, "[x, y, z]");
  EXPECT_EQ(uav.rows.at(1).default_text, "[50.0,50.0,10.0] m");
  const SettingsSection crowd = SettingsSectionNamed("mobility.crowd");
  EXPECT_EQ(crowd.rows.at(0).key, "ues.<i>.mobility.target");
  EXPECT_EQ(crowd.rows.at(0).default_text, "required");
  EXPECT_EQ(ErrorOf(ShippedScenarioDocument("b"), {"ues.0.mobility={\"model\": \"crowd\"}"}),
            "/ues/0/mobility/target: is required ([x, y]: where the crowd gathers)");
}

TEST(DefaultSets, EachOneParsesOnAShippedScenario) {
  for (const DefaultSet& set : DefaultSets()) {
    json doc = ShippedScenarioDocument("b");
    ApplyOverrides(doc, set.overrides);
    EXPECT_NO_THROW(ParseScenario(doc)) << set.name;
  }
  EXPECT_THROW(DefaultSetNamed("a2c"), std::invalid_argument);
}

TEST(DefaultSets, TheAnyScenarioSetsSizeThePolicyForManyScenarios) {
  json doc = ShippedScenarioDocument("b");
  ApplyOverrides(doc, AnyScenarioDefaults(3).overrides);
  const Scenario s = ParseScenario(doc);
  EXPECT_EQ(s.agent.algorithm, "ppo");
  EXPECT_EQ(s.env.fidelity, "analytic");
  EXPECT_EQ(s.agent.hidden, (std::vector<int>{128, 128}));
  EXPECT_EQ(s.agent.ppo.num_envs, 16);
  EXPECT_EQ(s.env.observations.back(), "others");  // several UAVs see each other
  EXPECT_EQ(AnyScenarioDefaults(1).name, "any-scenario");
  EXPECT_EQ(AlgorithmDefaults("sac").overrides.back(), "env.action_space=continuous");
}

TEST(Settings, SectionsByName) {
  EXPECT_EQ(SettingsSectionNamed("wifi").path, "/wifi");
  EXPECT_EQ(SettingsSectionNamed("ppo").path, "/agent/ppo");
  EXPECT_THROW(SettingsSectionNamed("wlan"), std::invalid_argument);
  const json all = SettingsSectionsJson(AllSettingsSections());
  ASSERT_TRUE(all.is_array());
  EXPECT_EQ(all.at(0).at("section"), "scenario");
  EXPECT_EQ(all.at(0).at("path"), "");
  EXPECT_EQ(all.at(0).at("settings").at(3).at("key"), "log_level");
  EXPECT_EQ(all.at(0).at("settings").at(3).at("default"), "warning");
  const json wifi = all.at(9);
  EXPECT_EQ(wifi.at("section"), "wifi");
  EXPECT_EQ(wifi.at("settings").at(5).at("key"), "wifi.tx_power");
  EXPECT_EQ(wifi.at("settings").at(5).at("default"), 20.0);
  EXPECT_EQ(wifi.at("settings").at(5).at("unit"), "dBm");
}

// The documents shipped to be run: campaigns/scenarios/*.json and each policy folder's
// scenario.json.
std::vector<std::filesystem::path> ShippedScenarioFiles() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path source(RLPOS_SOURCE_DIR);
  for (const auto& file : std::filesystem::directory_iterator(source / "campaigns/scenarios")) {
    if (file.path().extension() == ".json")
      out.push_back(file.path());
  }
  for (const auto& folder : std::filesystem::directory_iterator(source / "policies")) {
    if (std::filesystem::exists(folder.path() / "scenario.json"))
      out.push_back(folder.path() / "scenario.json");
  }
  return out;
}

// describe settings --json's keys, each with its type.
using Listed = std::map<std::string, std::string>;

// Whether `key` is a listed setting, holds some (a section, a list's element, "env.reward"), or
// is one its parent's shape names (the "model" of a UE's {"model", ...} mobility).
bool IsListed(const Listed& listed, const std::string& key) {
  const auto next = listed.lower_bound(key);
  if (next != listed.end() && (next->first == key || next->first.rfind(key + ".", 0) == 0))
    return true;
  const auto dot = key.rfind('.');
  const auto parent = dot == std::string::npos ? listed.end() : listed.find(key.substr(0, dot));
  return parent != listed.end() &&
         parent->second.find('"' + key.substr(dot + 1) + '"') != std::string::npos;
}

// The dotted keys of `value` below `prefix` as describe settings names them (a list's elements
// "<i>", those of "uavs" the uav table's), down to the listed settings: a setting's own value
// ([x, y, z], an ns-3 object's attributes) has no keys of the docs.
void CollectKeys(const json& value, const std::string& prefix, const Listed& listed,
                 std::set<std::string>& out) {
  if (value.is_array()) {
    const std::string element = prefix == "uavs" ? "uav" : prefix + ".<i>";
    for (const json& item : value)
      CollectKeys(item, element, listed, out);
    return;
  }
  if (!value.is_object())
    return;
  for (const auto& [name, child] : value.items()) {
    const std::string key = prefix.empty() ? name : prefix + "." + name;
    out.insert(key);
    // Descends only where the key holds listed ones (a mobility's keys under its row).
    const auto next = listed.upper_bound(key);
    if (!listed.count(key) || (next != listed.end() && next->first.rfind(key + ".", 0) == 0))
      CollectKeys(child, key, listed, out);
  }
}

TEST(Settings, EveryKeyOfAShippedScenarioIsListed) {
  Listed listed;
  for (const auto& section : SettingsSectionsJson(AllSettingsSections())) {
    for (const auto& row : section.at("settings"))
      listed[row.at("key").get<std::string>()] = row.at("type").get<std::string>();
  }
  const auto files = ShippedScenarioFiles();
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    std::set<std::string> keys;
    CollectKeys(ReadJsonFile(file.string()), "", listed, keys);
    for (const std::string& key : keys)
      EXPECT_TRUE(IsListed(listed, key)) << file << ": " << key;
  }
  for (const char* top :
       {"name", "description", "propagation", "log_level", "buildings", "ues", "uav", "uavs"})
    EXPECT_EQ(listed.count(top), 1u) << top;
}

}  // namespace
}  // namespace rlpos
