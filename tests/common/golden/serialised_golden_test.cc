// What the code serialises today, byte for byte, so that a rewrite of the settings' parsing and
// writing (scenario, env, Wi-Fi, agent) shows any byte it changes. One golden file per item,
// under tests/common/golden/data/, named after its input:
//   scenarios/<name>.json        campaigns/scenarios/<name>.json parsed and written back
//                                (ToJson(Scenario).dump(2), as a policy folder's scenario.json)
//   defaults/<name>.json         the same scenario with every key the parser can do without left
//                                out, written back: each default, since the shipped files state
//                                most settings (every Wi-Fi one) and so would not show a default
//                                that changed
//   policies/<folder>/scenario.json  the same of the folder's scenario.json (the agent's
//                                hyperparameters and every env and Wi-Fi setting included)
//   policies/<folder>/result.json    what the policy reader takes from result.json (seed stream,
//                                general policy's scope), written as result.json lays it out
//   campaigns/<name>.txt         campaigns/<name>.json: its id, the hash of each scenario as its
//                                jobs parse it, and every job as the store and the result cache
//                                identify it (content base, position rule's hash), in
//                                expansion order
//   generate/<name>.json         rlpos-sim generate's document for a seed, style, UAV count and
//                                mobility
// A failure names the golden file and shows its first differing line.
//
// To regenerate every golden file (and delete those whose input is gone) after a change that is
// meant: RLPOS_UPDATE_GOLDEN=1 build/bin/rlpos_common_golden_tests, then review the diff of
// tests/common/golden/data/ before committing it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/campaign/job_content.h"
#include "common/config/config_error.h"
#include "common/hash/sha256.h"
#include "common/job/job_fields.h"
#include "common/provenance/provenance.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_generator/generated_mobility.h"
#include "common/scenario_generator/scenario_generator.h"
#include "tests/common/golden/golden_file.h"
#include "worker/learning/policy_folder/policy_folder.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;
using golden::MatchesGolden;
using nlohmann::json;

// A job's content hashes the build it ran on (a commit's version); the golden files hash this
// one instead, so that they hold across commits and change only with what a job is.
constexpr const char* kPinnedBuild = "golden";

// One golden file and the input it is made from (relative to the source tree).
struct Item {
  std::string golden;
  std::string input;
};

std::string Source(const std::string& relative) {
  return std::string(RLPOS_SOURCE_DIR) + "/" + relative;
}

// The entries of a source folder whose names end with `suffix` ("" for folders), sorted.
std::vector<std::string> Listed(const std::string& folder, const std::string& suffix) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(Source(folder))) {
    const std::string name = entry.path().filename().string();
    const bool wanted =
        suffix.empty() ? entry.is_directory()
                       : entry.is_regular_file() && name.size() > suffix.size() &&
                             name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    if (wanted)
      names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string Stem(const std::string& file) {
  return fs::path(file).stem().string();
}

std::vector<Item> ScenarioItems() {
  std::vector<Item> items;
  for (const std::string& file : Listed("campaigns/scenarios", ".json"))
    items.push_back({"scenarios/" + file, "campaigns/scenarios/" + file});
  return items;
}

std::vector<Item> DefaultItems() {
  std::vector<Item> items;
  for (const std::string& file : Listed("campaigns/scenarios", ".json"))
    items.push_back({"defaults/" + file, "campaigns/scenarios/" + file});
  return items;
}

// Each policy folder's scenario.json and result.json, those it has.
std::vector<Item> PolicyItems() {
  std::vector<Item> items;
  for (const std::string& folder : Listed("policies", "")) {
    for (const char* file : {"scenario.json", "result.json"}) {
      const std::string input = "policies/" + folder + "/" + file;
      if (fs::exists(Source(input)))
        items.push_back({input, input});
    }
  }
  return items;
}

std::vector<Item> CampaignItems() {
  std::vector<Item> items;
  for (const std::string& file : Listed("campaigns", ".json"))
    items.push_back({"campaigns/" + Stem(file) + ".txt", "campaigns/" + file});
  return items;
}

struct GeneratorItem {
  std::string golden;
  std::uint64_t seed;
  std::optional<GeneratorStyle> style;  // unset: the seed's
  int uavs;
  std::string mobility;  // --mobility; "" for static UEs
};

// Every style with one and with three UAVs, each mobility model once, and a seed that picks its
// own style at the top of the seed range.
std::vector<GeneratorItem> GeneratorItems() {
  const auto urban = GeneratorStyle::kUrban, campus = GeneratorStyle::kCampus,
             suburb = GeneratorStyle::kSuburb, open = GeneratorStyle::kOpen;
  return {
      {"generate/urban-s1-1uav.json", 1, urban, 1, ""},
      {"generate/urban-s5-3uav.json", 5, urban, 3, ""},
      {"generate/campus-s2-1uav.json", 2, campus, 1, ""},
      {"generate/campus-s6-3uav.json", 6, campus, 3, ""},
      {"generate/suburb-s3-1uav.json", 3, suburb, 1, ""},
      {"generate/suburb-s7-3uav.json", 7, suburb, 3, ""},
      {"generate/open-s4-1uav.json", 4, open, 1, ""},
      {"generate/open-s8-3uav.json", 8, open, 3, ""},
      {"generate/campus-s9-1uav-random_waypoint.json", 9, campus, 1, "random_waypoint"},
      {"generate/urban-s10-3uav-gauss_markov.json", 10, urban, 3, "gauss_markov"},
      {"generate/suburb-s11-1uav-crowd.json", 11, suburb, 1, "crowd"},
      {"generate/seed-s18446744073709551615-1uav.json", UINT64_MAX, std::nullopt, 1, ""},
  };
}

std::string ScenarioText(const Scenario& scenario) {
  return ToJson(scenario).dump(2) + "\n";
}

bool Parses(const json& document) {
  try {
    ParseScenario(document);
    return true;
  } catch (const ConfigError&) {
    return false;
  }
}

// Leaves out of `node` (inside `document`) each key the parser accepts the document without,
// innermost first. Lists of objects (UEs, UAVs, buildings) stay, so that each element's own
// defaults are written back too.
void LeaveOutWhatDefaults(json& document, json& node) {
  if (node.is_array()) {
    for (json& element : node)
      LeaveOutWhatDefaults(document, element);
    return;
  }
  if (!node.is_object())
    return;
  std::vector<std::string> keys;
  for (const auto& entry : node.items())
    keys.push_back(entry.key());
  for (const std::string& key : keys) {
    LeaveOutWhatDefaults(document, node[key]);
    const bool list_of_objects =
        node[key].is_array() && !node[key].empty() && node[key].front().is_object();
    if (list_of_objects)
      continue;
    json kept = std::move(node[key]);
    node.erase(key);
    if (!Parses(document))
      node[key] = std::move(kept);
  }
}

std::string DefaultsText(const std::string& input) {
  json document = ReadJsonFile(Source(input));
  LeaveOutWhatDefaults(document, document);
  return ScenarioText(ParseScenario(document));
}

// The fields of result.json that ReadPolicyFolder reads, laid out as training writes them:
// the seed stream by SeedStreamJson, then the scope a general policy states.
std::string PolicyResultText(const std::string& folder) {
  const sim::PolicyFolder policy = sim::ReadPolicyFolder(folder);
  json result = sim::SeedStreamJson(policy.first_episode_run, policy.eval_run);
  result["general"] = policy.scope.general;
  if (policy.scope.general)
    result["training"] = {{"uavs", {policy.scope.min_uavs, policy.scope.max_uavs}}};
  return result.dump(2) + "\n";
}

// What identifies a job to the store and the result cache: its key, the key it depends on, its
// content base (the hash of its fields, as the cache reads them) and its position rule (a
// hash: an offsets rule holds the buildings). Train, position and track jobs are cached under
// their content base; an eval under the base and the placement its dependency gives at run time.
std::string JobLine(const Job& job, const std::string& campaign_id,
                    const std::string& scenario_sha256) {
  const std::string prefix = campaign_id + "/";
  const std::string depends_on =
      job.depends_on.empty()
          ? "-"
          : job.depends_on.substr(job.depends_on.rfind(prefix, 0) == 0 ? prefix.size() : 0);
  return "job " + job.key + " label=" + job.label + " depends_on=" + depends_on +
         " content_base=" + JobContentBase(job.params, scenario_sha256, kPinnedBuild) +
         " position_rule=" + Sha256Hex(ToJson(job.position_rule).dump()).substr(0, 16) + "\n";
}

std::string CampaignText(const std::string& input) {
  const ExpandedCampaign campaign = ExpandCampaign(ReadCampaignFile(Source(input)));
  std::string text = "# " + input + " as the store keeps it (tests/common/golden)\n";
  text += "id " + campaign.id + "\n";
  text += "name " + campaign.name + "\n";
  text += "max_attempts " + std::to_string(campaign.max_attempts) + "\n";
  text += "job_timeout_s " + json(campaign.job_timeout_s).dump() + "\n";
  text += "job_count " + std::to_string(campaign.JobCount()) + "\n";
  // The id above hashes the campaign's text; each scenario as its jobs parse it (with the
  // campaign's "set"), by the hash of its ToJson (tests/common/golden/data/scenarios has the
  // shipped ones written out).
  std::map<std::string, std::string> sha256_of;  // scenario name -> its document's, as hashed
  for (const CampaignScenario& s : campaign.parsed.scenarios) {
    sha256_of[s.scenario.name] = Sha256Hex(s.document.dump());
    text += "scenario " + s.scenario.name + " " + Sha256Hex(ToJson(s.scenario).dump()) + "\n";
  }
  const std::string build = ThisBuild().rlpos_version;
  for (const Job& job : campaign.jobs) {
    const std::string& sha256 = sha256_of.at(job.params.scenario);
    // The golden content base is worth pinning only if it is the one the cache uses.
    EXPECT_EQ(JobContentBase(job.params, sha256, build), job.content_base)
        << input << " " << job.key;
    text += JobLine(job, campaign.id, sha256);
  }
  return text;
}

std::string GeneratedText(const GeneratorItem& item) {
  GeneratorOptions options;
  options.seed = item.seed;
  options.style = item.style;
  options.uavs = item.uavs;
  if (!item.mobility.empty())
    options.mobility = ParseGeneratedMobility(item.mobility, "--mobility");
  return GenerateScenario(options).json_text;
}

TEST(SerialisedGolden, ShippedScenariosWrittenBack) {
  const std::vector<Item> items = ScenarioItems();
  ASSERT_FALSE(items.empty());
  for (const Item& item : items) {
    const std::string text = ScenarioText(ParseScenario(ReadJsonFile(Source(item.input))));
    EXPECT_TRUE(MatchesGolden(item.golden, text)) << "from " << item.input;
  }
}

TEST(SerialisedGolden, ShippedScenariosWithTheirDefaults) {
  const std::vector<Item> items = DefaultItems();
  ASSERT_FALSE(items.empty());
  for (const Item& item : items)
    EXPECT_TRUE(MatchesGolden(item.golden, DefaultsText(item.input))) << "from " << item.input;
}

TEST(SerialisedGolden, PolicyFoldersSettings) {
  const std::vector<Item> items = PolicyItems();
  ASSERT_FALSE(items.empty());
  for (const Item& item : items) {
    const std::string folder = Source(fs::path(item.input).parent_path().string());
    const std::string text = fs::path(item.input).filename() == "scenario.json"
                                 ? ScenarioText(ParseScenario(ReadJsonFile(Source(item.input))))
                                 : PolicyResultText(folder);
    EXPECT_TRUE(MatchesGolden(item.golden, text)) << "from " << item.input;
  }
}

TEST(SerialisedGolden, CampaignIdsAndJobIdentities) {
  const std::vector<Item> items = CampaignItems();
  ASSERT_FALSE(items.empty());
  for (const Item& item : items)
    EXPECT_TRUE(MatchesGolden(item.golden, CampaignText(item.input))) << "from " << item.input;
}

TEST(SerialisedGolden, GeneratedScenarios) {
  for (const GeneratorItem& item : GeneratorItems())
    EXPECT_TRUE(MatchesGolden(item.golden, GeneratedText(item)));
}

// A golden file whose input is gone would pin nothing; regenerating deletes it.
TEST(SerialisedGolden, NoGoldenFileWithoutItsInput) {
  std::set<std::string> expected;
  for (const auto& items : {ScenarioItems(), DefaultItems(), PolicyItems(), CampaignItems()}) {
    for (const Item& item : items)
      expected.insert(item.golden);
  }
  for (const GeneratorItem& item : GeneratorItems())
    expected.insert(item.golden);
  for (const std::string& name : golden::GoldenFilesOnDisk()) {
    if (expected.count(name) != 0)
      continue;
    if (golden::UpdatingGolden()) {
      fs::remove(golden::GoldenDir() + "/" + name);
    } else {
      ADD_FAILURE() << golden::RepositoryPath(name)
                    << " has no input any more; RLPOS_UPDATE_GOLDEN=1 deletes it";
    }
  }
}

TEST(GoldenFile, FirstDifferenceNamesLineAndColumn) {
  EXPECT_EQ(golden::FirstDifference("a\nb\n", "a\nb\n"), "");
  EXPECT_EQ(golden::FirstDifference("a\n\"width\": 160\n", "a\n\"width\": 80\n"),
            "first difference at line 2, column 10:\n"
            "  golden: \"width\": 160\n"
            "  now:    \"width\": 80");
  EXPECT_NE(golden::FirstDifference("a\n", "a\nb\n").find("(the text ends before this line)"),
            std::string::npos);
  EXPECT_NE(golden::FirstDifference("a\n", "a").find("newline"), std::string::npos);
  // A long line is shown around its first difference, not whole.
  const std::string long_golden = std::string(1000, 'x') + "A" + std::string(1000, 'y');
  const std::string long_now = std::string(1000, 'x') + "B" + std::string(1000, 'y');
  const std::string shown = golden::FirstDifference(long_golden, long_now);
  EXPECT_NE(shown.find("column 1001"), std::string::npos) << shown;
  EXPECT_NE(shown.find("xA"), std::string::npos) << shown;
  EXPECT_LT(shown.size(), 500u) << shown;
}

}  // namespace
}  // namespace rlpos
