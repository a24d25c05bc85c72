// rlpos-sim generate as a user runs it: a scenario rlpos-sim validate accepts, the same bytes on
// stdout, in a file and across processes, one-line errors for bad options and nothing written;
// and scripts/generate_scenario_set.sh's sets, disjoint.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "tests/support/command.h"
#include "tests/support/temp_dir.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

void ExpectOneLineError(const CommandResult& r, const std::string& fragment) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << "stdout must stay empty on failure: " << r.out;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(r.err.find("rlpos-sim: error: "), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(RlposSimGenerate, WritesAScenarioThatValidates) {
  TempDir dir;
  const auto r = RunCommand(Sim("generate --seed 5 --style campus --uavs 2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  WriteFile(dir.File("campus.json"), r.out);
  const auto v = RunCommand(Sim("validate --json " + dir.File("campus.json")));
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const auto summary = nlohmann::json::parse(v.out);
  EXPECT_EQ(summary["uavs"].size(), 2u);
  EXPECT_EQ(summary["ues"], 14);  // campus: 10, and 4 more for the second UAV
  EXPECT_LT(summary["n_los_at_baseline"].get<int>(), 14) << "a UE is NLoS at the baseline";
}

TEST(RlposSimGenerate, SameSeedSameBytesInAFileAndAcrossProcesses) {
  TempDir dir;
  const auto first = RunCommand(Sim("generate --seed 17 --style urban"));
  const auto second = RunCommand(Sim("generate --seed 17 --style urban"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(first.out, second.out);
  const auto to_file =
      RunCommand(Sim("generate --seed 17 --style urban --out " + dir.File("u.json")));
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  EXPECT_TRUE(to_file.out.empty());
  EXPECT_EQ(ReadFile(dir.File("u.json")), first.out);
  EXPECT_NE(RunCommand(Sim("generate --seed 18 --style urban")).out, first.out);
}

TEST(RlposSimGenerate, MobilityMovesEveryUeAndValidateSaysHow) {
  TempDir dir;
  const auto r = RunCommand(Sim("generate --seed 3 --style open --mobility gauss_markov"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(RunCommand(Sim("generate --seed 3 --style open --mobility gauss_markov")).out, r.out);
  const auto document = nlohmann::json::parse(r.out);
  for (const auto& ue : document["ues"])
    EXPECT_EQ(ue["mobility"]["model"], "gauss_markov");
  WriteFile(dir.File("open.json"), r.out);
  const auto v = RunCommand(Sim("validate " + dir.File("open.json")));
  ASSERT_EQ(v.exit_code, 0) << v.err;
  EXPECT_NE(v.out.find("  mobility    10 UEs: gauss_markov at 1 m/s, alpha 0.75, step 1 s\n"),
            std::string::npos)
      << v.out;
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --mobility teleport")),
                     "--mobility: unknown mobility \"teleport\"");
}

TEST(RlposSimGenerate, TheSeedChoosesTheStyleWhenNoneIsGiven) {
  const auto r = RunCommand(Sim("generate --seed 6"));  // 6 mod 4: suburb
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["name"], "gen-suburb-1uav-s6");
}

TEST(RlposSimGenerate, BadOptionsAreOneLineErrors) {
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --style downtown")),
                     "--style: unknown style \"downtown\" (urban, campus, suburb or open)");
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --uavs 0")),
                     "--uavs: 0 is out of range (1 to 6)");
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --uavs 7")),
                     "--uavs: 7 is out of range (1 to 6)");
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --ues 0")),
                     "--ues: 0 is out of range (1 to 100)");
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --ues 1000000")),
                     "--ues: 1000000 is out of range (1 to 100)");
  ExpectOneLineError(RunCommand(Sim("generate --seed -1")), "--seed: \"-1\" is not a whole number");
  ExpectOneLineError(RunCommand(Sim("generate --seed=-1")), "--seed: \"-1\" is not a whole number");
  ExpectOneLineError(RunCommand(Sim("generate --seed 2.5")),
                     "--seed: \"2.5\" is not a whole number");
  ExpectOneLineError(RunCommand(Sim("generate --seed 99999999999999999999")),
                     "--seed: 99999999999999999999 is out of range");
  const auto missing = RunCommand(Sim("generate --style urban"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_TRUE(missing.out.empty());
}

TEST(RlposSimGenerate, AnUnwritableOutLeavesNothingBehind) {
  TempDir dir;
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --out " + dir.File("no/such/dir.json"))),
                     "--out: cannot write " + dir.File("no/such/dir.json"));
  // A folder where the file should go: the rename fails, and the temporary file goes too.
  std::filesystem::create_directory(dir.File("taken"));
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --out " + dir.File("taken"))),
                     "--out: cannot write " + dir.File("taken"));
  // A bad option leaves an existing file as it was.
  WriteFile(dir.File("kept.json"), "old");
  ExpectOneLineError(RunCommand(Sim("generate --seed 1 --uavs 9 --out " + dir.File("kept.json"))),
                     "--uavs");
  EXPECT_EQ(ReadFile(dir.File("kept.json")), "old");
  std::size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 2u) << "only taken/ and kept.json";
}

// Tab-separated text as rows of its cells, its header line left out.
std::vector<std::vector<std::string>> TsvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    std::vector<std::string> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, '\t'))
      row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

std::string SetScript() {
  return std::string(RLPOS_SOURCE_DIR) + "/scripts/generate_scenario_set.sh";
}

// Every set's listing (file, seed, style, uavs): its styles and UAV counts, and no seed in two
// sets. Listed, not generated: the same loop writes them (one set is written below).
TEST(GenerateScenarioSet, TheSetsAreDisjointAndCoverTheStyles) {
  std::map<std::string, std::set<std::string>> seeds;
  for (const std::string set :
       {"train",  "tune",        "tune-many", "heldout",      "train-many", "heldout-many",
        "fresh",  "fresh-many",  "confirm",   "confirm-many", "audit",      "audit-many",
        "verify", "verify-many", "check",     "check-many",   "vet",        "vet-many",
        "trial",  "trial-many",  "probe",     "probe-many",   "gauge",      "gauge-many",
        "assay",  "assay-many"}) {
    const auto r = RunCommand(SetScript() + " --set " + set + " --list");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::map<std::string, int> one_uav, more_uavs;      // per style
    std::map<std::string, std::set<std::string>> uavs;  // per style: its UAV counts
    for (const auto& row : TsvRows(r.out)) {
      ASSERT_EQ(row.size(), 4u) << set;
      EXPECT_EQ(row[0], row[2] + "-" + row[3] + "uav-s" + row[1] + ".json") << set;
      EXPECT_TRUE(seeds[set].insert(row[1]).second) << set << ": seed " << row[1] << " twice";
      (row[3] == "1" ? one_uav : more_uavs)[row[2]] += 1;
      uavs[row[2]].insert(row[3]);
    }
    if (set.size() > 5 && set.substr(set.size() - 5) == "-many") {
      EXPECT_EQ(uavs.size(), 4u) << set << ": every style";
      // train-many and heldout-many add 4-6 UAVs to train and heldout; the others are 2-6.
      const std::set<std::string> want = set == "train-many" || set == "heldout-many"
                                             ? std::set<std::string>{"4", "5", "6"}
                                             : std::set<std::string>{"2", "3", "4", "5", "6"};
      for (const auto& [style, counts] : uavs)
        EXPECT_EQ(counts, want) << set << ", " << style;
      continue;
    }
    if (set != "train" && set != "heldout") {  // one UAV: 16 or 32 per style
      const int each = set == "fresh" ? 16 : 32;
      EXPECT_TRUE(more_uavs.empty()) << set;
      EXPECT_EQ(one_uav, (std::map<std::string, int>{
                             {"urban", each}, {"campus", each}, {"suburb", each}, {"open", each}}));
      continue;
    }
    EXPECT_EQ(one_uav.size(), 4u) << set << ": every style with one UAV";
    EXPECT_EQ(more_uavs.size(), 4u) << set << ": every style with two or three";
    if (set == "heldout") {
      int one = 0, more = 0;
      for (const auto& [style, n] : one_uav)
        one += n;
      for (const auto& [style, n] : more_uavs)
        more += n;
      EXPECT_GE(one, 30);
      EXPECT_GE(more, 15);
    }
  }
  for (const auto& [set, mine] : seeds) {
    for (const auto& [other, theirs] : seeds) {
      for (const auto& seed : mine) {
        if (set != other) {
          EXPECT_EQ(theirs.count(seed), 0u) << "seed " << seed << " in " << set << " and " << other;
        }
      }
    }
  }
}

// A set written: the scenarios of its listing, each generated from its seed and valid, with
// their UE counts; never written over another.
TEST(GenerateScenarioSet, WritesTheScenariosItListsAndNeverOverAnother) {
  TempDir dir;
  const std::string build =
      std::filesystem::path(BuiltBinary("rlpos-sim")).parent_path().parent_path();
  const std::string out = dir.File("train");
  const auto r = RunCommand(SetScript() + " --set train --out " + out + " --build " + build);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto listed = TsvRows(RunCommand(SetScript() + " --set train --list").out);
  const auto written = TsvRows(ReadFile(out + "/index.tsv"));
  ASSERT_EQ(written.size(), listed.size());
  ASSERT_EQ(written.size(), 48u);
  for (std::size_t i = 0; i < written.size(); ++i) {
    ASSERT_EQ(written[i].size(), 5u);
    EXPECT_EQ(std::vector<std::string>(written[i].begin(), written[i].begin() + 4), listed[i]);
    const std::string file = out + "/" + written[i][0];
    const nlohmann::json doc = nlohmann::json::parse(ReadFile(file));
    EXPECT_EQ(std::to_string(doc["ues"].size()), written[i][4]) << file;
    // One UAV is written as "uav", several as "uavs".
    const std::size_t uavs = doc.contains("uavs") ? doc["uavs"].size() : doc.count("uav");
    EXPECT_EQ(std::to_string(uavs), written[i][3]) << file;
  }
  // The first scenario is what rlpos-sim generate makes from its seed.
  const std::string again = dir.File("again.json");
  ASSERT_EQ(RunCommand(Sim("generate --seed " + written[0][1] + " --style " + written[0][2] +
                           " --uavs " + written[0][3] + " --out " + again))
                .exit_code,
            0);
  EXPECT_EQ(ReadFile(again), ReadFile(out + "/" + written[0][0]));
  const auto over = RunCommand(SetScript() + " --set train --out " + out + " --build " + build);
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("exists and is not an empty folder"), std::string::npos) << over.err;
  EXPECT_EQ(RunCommand(SetScript() + " --set train --list --out " + out).exit_code, 2);
}

}  // namespace
}  // namespace rlpos::testing
