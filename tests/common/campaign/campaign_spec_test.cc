#include "common/campaign/campaign_spec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "common/campaign/expansion.h"
#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "tests/support/campaign_fixtures.h"

namespace rlpos {
namespace {

using nlohmann::json;
using testing::SourcePath;
using testing::TempDir;
using testing::WriteFile;

std::string ScenarioB() {
  return SourcePath("campaigns/scenarios/b.json");
}
std::string ScenarioC() {
  return SourcePath("campaigns/scenarios/c.json");
}

json MinimalCampaign() {
  return {{"name", "t"}, {"scenarios", {ScenarioB()}}, {"rng_runs", {1, 2}}};
}

TEST(CampaignSpec, ShippedCampaignsParseAndExpand) {
  const CampaignSpec mini = ReadCampaignFile(SourcePath("campaigns/mini.json"));
  ASSERT_EQ(mini.scenarios.size(), 2u);
  EXPECT_EQ(mini.scenarios[0].scenario.name, "B");
  EXPECT_EQ(mini.scenarios[1].scenario.name, "C");
  EXPECT_EQ(mini.rng_runs, (std::vector<std::uint64_t>{1, 2}));
  EXPECT_EQ(mini.positioners, AllPositioners());
  EXPECT_EQ(mini.retries, 1);
  EXPECT_DOUBLE_EQ(mini.job_timeout_s, 300.0);
  EXPECT_DOUBLE_EQ(*mini.eval.duration, 2.0);
  EXPECT_DOUBLE_EQ(*mini.eval.warmup, 0.5);
  // The eval settings are part of the validated scenario.
  EXPECT_DOUBLE_EQ(mini.scenarios[0].scenario.simulation.duration, 2.0);
  EXPECT_DOUBLE_EQ(mini.scenarios[0].scenario.simulation.warmup, 0.5);
  // Per scenario: 3 position jobs + 1 train job + 2 runs x 9 labels.
  EXPECT_EQ(ExpandCampaign(mini).jobs.size(), 2u * (4 + 2 * 9));

  const CampaignSpec paper = ReadCampaignFile(SourcePath("campaigns/paper.json"));
  ASSERT_EQ(paper.scenarios.size(), 3u);
  EXPECT_EQ(paper.scenarios[0].scenario.name, "A");
  EXPECT_EQ(paper.rng_runs.size(), 30u);
  EXPECT_EQ(paper.rng_runs.front(), 1u);
  EXPECT_EQ(paper.rng_runs.back(), 30u);
  EXPECT_EQ(paper.train.seeds, (std::vector<std::uint64_t>{1}));
  EXPECT_EQ(paper.train.fidelity, "analytic");
  EXPECT_DOUBLE_EQ(*paper.eval.duration, 10.0);
  EXPECT_DOUBLE_EQ(*paper.eval.warmup, 1.0);
  EXPECT_EQ(ExpandCampaign(paper).jobs.size(), 3u * (4 + 30 * 9));
}

TEST(CampaignSpec, Defaults) {
  const CampaignSpec spec = ParseCampaign(MinimalCampaign(), "/");
  EXPECT_EQ(spec.name, "t");
  EXPECT_EQ(spec.positioners, AllPositioners());
  EXPECT_EQ(spec.retries, 2);
  EXPECT_DOUBLE_EQ(spec.job_timeout_s, 600.0);
  EXPECT_EQ(spec.train.seeds, (std::vector<std::uint64_t>{1}));
  EXPECT_EQ(spec.train.fidelity, "analytic");
  EXPECT_FALSE(spec.train.episodes.has_value());
  EXPECT_FALSE(spec.eval.duration.has_value());
  EXPECT_FALSE(spec.eval.warmup.has_value());
  EXPECT_TRUE(spec.NeedsTraining());
}

TEST(CampaignSpec, ScenarioPathsAreRelativeToTheCampaignFolder) {
  TempDir dir;
  std::filesystem::create_directories(dir.File("scenarios"));
  std::filesystem::copy_file(ScenarioB(), dir.File("scenarios/b.json"));
  WriteFile(dir.File("campaign.json"),
            R"({"name": "rel", "scenarios": ["scenarios/b.json"], "rng_runs": [3, 3]})");
  const CampaignSpec spec = ReadCampaignFile(dir.File("campaign.json"));
  ASSERT_EQ(spec.scenarios.size(), 1u);
  EXPECT_EQ(spec.scenarios[0].file, "scenarios/b.json");
  EXPECT_EQ(spec.scenarios[0].path,
            std::filesystem::path(dir.File("scenarios/b.json")).lexically_normal().string());
  EXPECT_EQ(spec.rng_runs, (std::vector<std::uint64_t>{3}));
}

TEST(CampaignSpec, ListOfRunsIsSorted) {
  json doc = MinimalCampaign();
  doc["rng_runs"] = {{"list", {5, 1, 2}}};
  EXPECT_EQ(ParseCampaign(doc, "/").rng_runs, (std::vector<std::uint64_t>{1, 2, 5}));
}

TEST(CampaignSpec, PositionersTakeTheCanonicalOrder) {
  json doc = MinimalCampaign();
  doc["positioners"] = {"rl", "baseline"};
  const CampaignSpec spec = ParseCampaign(doc, "/");
  EXPECT_EQ(spec.positioners, (std::vector<std::string>{"baseline", "rl"}));
  doc["positioners"] = {"centroid"};
  EXPECT_FALSE(ParseCampaign(doc, "/").NeedsTraining());
}

TEST(CampaignSpec, AlgorithmsTakeTheCanonicalOrder) {
  json doc = MinimalCampaign();
  doc["train"] = {{"algorithms", {"sac", "dqn", "ppo"}}};
  EXPECT_EQ(ParseCampaign(doc, "/").train.algorithms,
            (std::vector<std::string>{"dqn", "ppo", "sac"}));
  doc["train"] = {{"algorithms", {"ppo"}}};
  EXPECT_EQ(ToJson(ParseCampaign(doc, "/"))["train"]["algorithms"], json({"ppo"}));
}

TEST(CampaignSpec, AlgorithmsOverrideTheScenariosOwn) {
  // Every agent section is validated with the scenario itself; each algorithm's training then
  // sets agent.algorithm and the action space that goes with it. A "set" that says the same is
  // accepted; one that says otherwise is refused (job_settings_test.cc).
  json doc = MinimalCampaign();
  doc["scenarios"] = {
      {{"file", ScenarioB()}, {"set", {"agent.algorithm=sac", "env.action_space=continuous"}}}};
  doc["train"] = {{"algorithms", {"sac"}}};
  const CampaignSpec spec = ParseCampaign(doc, "/");
  EXPECT_EQ(spec.train.algorithms, (std::vector<std::string>{"sac"}));
  doc["train"] = {{"algorithms", {"dqn", "ppo"}}};
  EXPECT_THROW(ParseCampaign(doc, "/"), ConfigError);
}

TEST(CampaignSpec, SetOverridesTheScenario) {
  json doc = MinimalCampaign();
  doc["scenarios"] = {
      {{"file", ScenarioC()}, {"set", {"simulation.duration=5", "wifi.mode=adhoc"}}}};
  const CampaignSpec spec = ParseCampaign(doc, "/");
  EXPECT_EQ(spec.scenarios[0].overrides,
            (std::vector<std::string>{"simulation.duration=5", "wifi.mode=adhoc"}));
  EXPECT_DOUBLE_EQ(spec.scenarios[0].scenario.simulation.duration, 5.0);
  EXPECT_EQ(spec.scenarios[0].scenario.wifi.mode, "adhoc");
  // The document is kept as read: overrides travel separately, as the job's overrides.
  EXPECT_EQ(spec.scenarios[0].document, ReadJsonFile(ScenarioC()));
}

TEST(CampaignSpec, SameFileTwiceNeedsAnotherName) {
  json doc = MinimalCampaign();
  doc["scenarios"] = {ScenarioB(),
                      {{"file", ScenarioB()}, {"set", {"name=B-adhoc", "wifi.mode=adhoc"}}}};
  const CampaignSpec spec = ParseCampaign(doc, "/");
  EXPECT_EQ(spec.scenarios[1].scenario.name, "B-adhoc");
}

struct BadCampaign {
  const char* name;
  std::function<void(json&)> edit;
  std::string expected;  // "<path>: <start of problem>"
};

class CampaignSpecBadInput : public ::testing::TestWithParam<BadCampaign> {};

TEST_P(CampaignSpecBadInput, NamesPathAndProblem) {
  json doc = MinimalCampaign();
  GetParam().edit(doc);
  std::string error;
  try {
    ParseCampaign(doc, "/campaigns");
  } catch (const ConfigError& e) {
    error = e.describe();
  }
  EXPECT_NE(error.find(GetParam().expected), std::string::npos)
      << "got: \"" << error << "\", expected to contain: \"" << GetParam().expected << "\"";
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
}

// Each case edits a valid campaign ({"name", "scenarios": [B], "rng_runs": [1, 2]}).
const BadCampaign kBadCampaigns[] = {
    {"NotAnObject", [](json& d) { d = json::array(); }, "/: expected an object, got an array"},
    {"UnknownKey", [](json& d) { d["retires"] = 1; },
     "/retires: unknown key \"retires\"; did you mean \"retries\"?"},
    {"MisspeltRequiredKey",
     [](json& d) {
       d["rng_run"] = d["rng_runs"];
       d.erase("rng_runs");
     },
     "/rng_run: unknown key \"rng_run\"; did you mean \"rng_runs\"?"},
    {"MissingName", [](json& d) { d.erase("name"); }, "/name: is required"},
    {"EmptyName", [](json& d) { d["name"] = ""; }, "/name: must not be empty"},
    {"MissingScenarios", [](json& d) { d.erase("scenarios"); }, "/scenarios: is required"},
    {"NoScenarios", [](json& d) { d["scenarios"] = json::array(); },
     "/scenarios: expected a non-empty array, got an empty array"},
    {"ScenarioNotAFile", [](json& d) { d["scenarios"] = {42}; },
     "/scenarios/0: expected a file name or {\"file\", \"set\"}, got a number"},
    {"MissingScenarioFile", [](json& d) { d["scenarios"] = {"scenarios/nope.json"}; },
     "/scenarios/0: scenario file \"/campaigns/scenarios/nope.json\" does not exist"},
    {"MissingScenarioFileInObject",
     [](json& d) {
       d["scenarios"] = {{{"file", "/no/such.json"}}};
     },
     "/scenarios/0/file: scenario file \"/no/such.json\" does not exist"},
    {"ScenarioEntryUnknownKey",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"sett", json::array()}}};
     },
     "/scenarios/0/sett: unknown key \"sett\"; did you mean \"set\"?"},
    {"ScenarioEntryWithoutFile",
     [](json& d) {
       d["scenarios"] = {{{"fille", ScenarioB()}}};
     },
     "/scenarios/0/fille: unknown key \"fille\"; did you mean \"file\"?"},
    {"SetNotAList",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", "wifi.mode=adhoc"}}};
     },
     "/scenarios/0/set: expected an array, got a string"},
    {"SetItemNotAString",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", {1}}}};
     },
     "/scenarios/0/set/0: expected \"path=value\", got a number"},
    {"SetItemWithoutValue",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", {"novalue"}}}};
     },
     "/scenarios/0/set/0: expected path=value"},
    {"SetBreaksScenario",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", {"venue.width=-1"}}}};
     },
     "b.json: /venue/width: must be positive"},
    {"SetBadScenarioName",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", {"name=B/2"}}}};
     },
     "scenario name \"B/2\" must be 1-128 of [A-Za-z0-9._@+-]"},
    {"DuplicateScenarioName",
     [](json& d) {
       d["scenarios"] = {ScenarioB(), ScenarioB()};
     },
     "/scenarios/1: scenario name \"B\" is already used by /scenarios/0"},
    {"MissingRuns", [](json& d) { d.erase("rng_runs"); }, "/rng_runs: is required"},
    {"RunsReversed",
     [](json& d) {
       d["rng_runs"] = {3, 1};
     },
     "/rng_runs: first must not be above last"},
    {"RunsNotAPair",
     [](json& d) {
       d["rng_runs"] = {1, 2, 3};
     },
     "/rng_runs: expected [first, last] (2 numbers) or {\"list\": [...]}, got an array of 3"},
    {"RunsOfOne", [](json& d) { d["rng_runs"] = json::array({1}); },
     "/rng_runs: expected [first, last] (2 numbers) or {\"list\": [...]}, got an array of 1"},
    {"RunsNotAnArray", [](json& d) { d["rng_runs"] = "1-2"; },
     "/rng_runs: expected [first, last] (2 numbers) or {\"list\": [...]}, got a string"},
    {"RunFractional",
     [](json& d) {
       d["rng_runs"] = {1, 2.5};
     },
     "/rng_runs/1: expected a non-negative integer, got a fractional number"},
    {"RunNegative",
     [](json& d) {
       d["rng_runs"] = {-1, 2};
     },
     "/rng_runs/0: must not be negative, got -1"},
    {"TooManyRuns",
     [](json& d) {
       d["rng_runs"] = {1, 1000000};
     },
     "/rng_runs: more than 100000 runs"},
    {"RunListedTwice",
     [](json& d) {
       d["rng_runs"] = {{"list", {1, 2, 2}}};
     },
     "/rng_runs/list/2: 2 is listed twice"},
    {"RunListMisspelt",
     [](json& d) {
       d["rng_runs"] = {{"lst", {1}}};
     },
     "/rng_runs/lst: unknown key \"lst\"; did you mean \"list\"?"},
    {"UnknownPositioner",
     [](json& d) {
       d["positioners"] = {"baseline", "centriod"};
     },
     "/positioners/1: unknown positioner \"centriod\" (one of: baseline, offsets, centroid, "
     "oracle, rl); did you mean \"centroid\"?"},
    {"PositionerTwice",
     [](json& d) {
       d["positioners"] = {"rl", "rl"};
     },
     "/positioners/1: \"rl\" is listed twice"},
    {"NoPositioners", [](json& d) { d["positioners"] = json::array(); },
     "/positioners: expected a non-empty array"},
    {"BadFidelity",
     [](json& d) {
       d["train"] = {{"fidelity", "analitic"}};
     },
     "/train/fidelity: unknown value \"analitic\" (one of: analytic, packet); did you mean "
     "\"analytic\"?"},
    {"NoSeeds",
     [](json& d) {
       d["train"] = {{"seeds", json::array()}};
     },
     "/train/seeds: expected a non-empty array"},
    {"SeedTwice",
     [](json& d) {
       d["train"] = {{"seeds", {1, 1}}};
     },
     "/train/seeds/1: 1 is listed twice"},
    {"ZeroEpisodes",
     [](json& d) {
       d["train"] = {{"episodes", 0}};
     },
     "/train/episodes: must be in [1, 1000000], got 0"},
    {"TrainUnknownKey",
     [](json& d) {
       d["train"] = {{"seed", {1}}};
     },
     "/train/seed: unknown key \"seed\"; did you mean \"seeds\"?"},
    {"NegativeDuration",
     [](json& d) {
       d["eval"] = {{"duration", -1}};
     },
     "/eval/duration: must be positive, got -1"},
    {"WarmupTooLong",
     [](json& d) {
       d["eval"] = {{"duration", 2}, {"warmup", 2}};
     },
     "/eval/warmup: must be shorter than the duration"},
    {"WarmupLongerThanScenario",
     [](json& d) {
       d["eval"] = {{"warmup", 20}};
     },
     "/scenarios/0: " + ScenarioB() + ": /simulation/warmup: must be shorter than the duration"},
    {"NegativeRetries", [](json& d) { d["retries"] = -1; },
     "/retries: must be in [0, 100], got -1"},
    {"ZeroTimeout", [](json& d) { d["job_timeout_s"] = 0; },
     "/job_timeout_s: must be positive, got 0"},
    {"UnknownAlgorithm",
     [](json& d) {
       d["train"] = {{"algorithms", {"dqn", "ppo2"}}};
     },
     "/train/algorithms/1: unknown algorithm \"ppo2\" (one of: dqn, ppo, sac); did you mean "
     "\"ppo\"?"},
    {"AlgorithmTwice",
     [](json& d) {
       d["train"] = {{"algorithms", {"sac", "sac"}}};
     },
     "/train/algorithms/1: \"sac\" is listed twice"},
    {"NoAlgorithms",
     [](json& d) {
       d["train"] = {{"algorithms", json::array()}};
     },
     "/train/algorithms: expected a non-empty array"},
    {"AlgorithmSettingsInvalid",
     [](json& d) {
       d["scenarios"] = {{{"file", ScenarioB()}, {"set", {"agent.sac.batch_size=0"}}}};
     },
     "/scenarios/0: " + ScenarioB() + ": /agent/sac/batch_size: must be in [1, 65536], got 0"},
};

INSTANTIATE_TEST_SUITE_P(Cases, CampaignSpecBadInput, ::testing::ValuesIn(kBadCampaigns),
                         [](const ::testing::TestParamInfo<BadCampaign>& param) {
                           return param.param.name;
                         });

TEST(CampaignSpec, MalformedScenarioFileNamesIt) {
  TempDir dir;
  WriteFile(dir.File("broken.json"), "{\"name\": \"X\",,}");
  json doc = MinimalCampaign();
  doc["scenarios"] = {"broken.json"};
  try {
    ParseCampaign(doc, dir.path());
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.path(), "/scenarios/0");
    EXPECT_NE(e.problem().find("scenario file \"" + dir.File("broken.json") +
                               "\": malformed JSON at line 1"),
              std::string::npos)
        << e.problem();
  }
}

TEST(CampaignSpec, ScenarioThatIsNotAnObject) {
  TempDir dir;
  WriteFile(dir.File("list.json"), "[1, 2]");
  json doc = MinimalCampaign();
  doc["scenarios"] = {"list.json"};
  doc["eval"] = {{"duration", 3}};
  try {
    ParseCampaign(doc, dir.path());
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.path(), "/scenarios/0");
    EXPECT_EQ(e.problem().rfind("list.json: ", 0), 0u) << e.problem();
  }
}

TEST(CampaignSpec, MissingCampaignFileIsAConfigError) {
  EXPECT_THROW(ReadCampaignFile("/nonexistent/campaign.json"), ConfigError);
}

// What callers read back from a stored campaign: each entry's document with its "set" applied.
TEST(CampaignSpec, StatedScenarioDocumentAppliesTheEntrysSet) {
  const json spec = ToJson(ReadCampaignFile(SourcePath("campaigns/mini.json")));
  for (const json& entry : spec.at("scenarios")) {
    json stated = entry.at("document");
    ApplyOverrides(stated, entry.at("set").get<std::vector<std::string>>());
    EXPECT_EQ(StatedScenarioDocument(entry), stated);
  }
  const json entry = {
      {"file", "x.json"}, {"set", {"name=Y", "/wifi/mode=adhoc"}}, {"document", {{"name", "X"}}}};
  EXPECT_EQ(StatedScenarioDocument(entry), (json{{"name", "Y"}, {"wifi", {{"mode", "adhoc"}}}}));
}

TEST(CampaignSpec, StatedScenarioDocumentRefusesAMalformedEntry) {
  const auto error = [](const json& entry) {
    try {
      StatedScenarioDocument(entry);
    } catch (const ConfigError& e) {
      return e.describe();
    }
    return std::string();
  };
  const json document = {{"name", "X"}};
  EXPECT_EQ(error("x.json"), "/: expected an object, got a string");
  EXPECT_EQ(error({{"set", json::array()}}), "/document: expected an object, got nothing");
  EXPECT_EQ(error({{"set", json::array()}, {"document", json::array()}}),
            "/document: expected an object, got an array");
  EXPECT_EQ(error({{"document", document}}), "/set: expected an array, got nothing");
  EXPECT_EQ(error({{"document", document}, {"set", "name=Y"}}),
            "/set: expected an array, got a string");
  EXPECT_EQ(error({{"document", document}, {"set", {"name=Y", 2}}}), "/set/1: expected a string");
  EXPECT_EQ(error({{"document", document}, {"set", {"no-equals-sign"}}}),
            "--set no-equals-sign: expected path=value");
  EXPECT_EQ(error({{"document", document}, {"set", json::array()}}), "");
}

}  // namespace
}  // namespace rlpos
