// rlpos-sim import --from rlpos3 as a user runs it: a scenario `validate` accepts, the same
// bytes every time, a warning line per field not carried, and bad input as one error line
// with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/command.h"
#include "tests/support/temp_dir.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

const std::string kSource = RLPOS_SOURCE_DIR;
const std::string kFull = kSource + "/tests/common/scenario_import/data/rlpos3_full.json";
const std::string kExample = kSource + "/docs/examples/rlpos3-input.json";

std::size_t Lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(RlposSimImport, PrintsAScenarioThatValidates) {
  TempDir dir;
  const auto r = RunCommand(Sim("import --from rlpos3 " + kFull));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // One line per warning, each naming the file and a JSON path of the source.
  EXPECT_EQ(Lines(r.err), 24u) << r.err;
  EXPECT_NE(r.err.find("rlpos-sim: warning: " + kFull +
                       ": /ns3Sim/defaultValues/UENodes/1/DataRate: 50 Mbit/s rounded up to MCS 1"),
            std::string::npos)
      << r.err;
  const auto scenario = nlohmann::json::parse(r.out);
  EXPECT_EQ(scenario["ues"][1]["demand"], nlohmann::json({{"mcs", 1}}));
  EXPECT_EQ(scenario["ues"][1]["position"], nlohmann::json({90.0, 90.0, 1.5}));
  WriteFile(dir.File("full.json"), r.out);
  const auto validated = RunCommand(Sim("validate " + dir.File("full.json")));
  EXPECT_EQ(validated.exit_code, 0) << validated.err;
  EXPECT_NE(validated.out.find("valid"), std::string::npos);
}

TEST(RlposSimImport, OutFileHoldsTheSameBytesEveryTime) {
  TempDir dir;
  const auto first = RunCommand(Sim("import --from rlpos3 " + kFull + " --out " + dir.File("a")));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(first.out.empty()) << first.out;
  const auto second = RunCommand(Sim("import --from rlpos3 " + kFull + " --out " + dir.File("b")));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(ReadFile(dir.File("a")), ReadFile(dir.File("b")));
  EXPECT_EQ(ReadFile(dir.File("a")), RunCommand(Sim("import --from rlpos3 " + kFull)).out);
  EXPECT_EQ(first.err, second.err);
}

// The docs' example (docs/rlpos3-import.md) imports into a scenario that validates.
TEST(RlposSimImport, DocsExampleValidates) {
  TempDir dir;
  const auto r =
      RunCommand(Sim("import --from rlpos3 " + kExample + " --out " + dir.File("example.json")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto validated = RunCommand(Sim("validate " + dir.File("example.json")));
  EXPECT_EQ(validated.exit_code, 0) << validated.err;
}

// `edit` is a Python expression statement over the config `c`; returns the edited file's path.
std::string Edited(const TempDir& dir, const std::string& edit) {
  const std::string file = dir.File("edited.json");
  const auto r = RunCommand("python3 -c 'import json,sys; c=json.load(open(sys.argv[1])); " + edit +
                            "; json.dump(c, open(sys.argv[2], \"w\"))' " + kFull + " " + file);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return file;
}

// Exit code 2, one line "rlpos-sim: error: ...<fragment>...", nothing on stdout, no --out file.
void ExpectRejected(const TempDir& dir, const std::string& args, const std::string& fragment) {
  const std::string out = dir.File("never.json");
  const auto r = RunCommand(Sim("import " + args + " --out " + out));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("rlpos-sim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_EQ(Lines(r.err), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

const std::string kHelsinki = std::string(RLPOS_SOURCE_DIR) + "/data/osm/helsinki-central.osm.pbf";
const std::string kSquare = " --center 60.1697,24.9505 --size 150x150 --ues 8 --seed 3";

TEST(RlposSimImport, ARealPlaceValidatesWithItsFootprintsAndTheSameBytesTwice) {
  TempDir dir;
  const auto first =
      RunCommand(Sim("import --from osm " + kHelsinki + kSquare + " --out " + dir.File("a.json")));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find("rlpos-sim: import: 150 x 150 m: "), std::string::npos) << first.err;
  const auto second =
      RunCommand(Sim("import --from osm " + kHelsinki + kSquare + " --out " + dir.File("b.json")));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(ReadFile(dir.File("a.json")), ReadFile(dir.File("b.json")));
  const auto validated = RunCommand(Sim("validate " + dir.File("a.json")));
  ASSERT_EQ(validated.exit_code, 0) << validated.err;
  const nlohmann::json scenario = nlohmann::json::parse(ReadFile(dir.File("a.json")));
  const std::size_t buildings = scenario["buildings"].size();
  ASSERT_GT(buildings, 0u);
  const std::string count = std::to_string(buildings);
  EXPECT_NE(validated.out.find("buildings   " + count + " (" + count + " footprints)"),
            std::string::npos)
      << validated.out;
}

// Here the building nearest the centre is 2 m long: the roof's even steps would put three UAVs
// 0.5 m apart, which the checks refuse; they stand 5 m apart instead.
TEST(RlposSimImport, SeveralUavsOverASmallRoofStandApart) {
  TempDir dir;
  const auto r = RunCommand(Sim("import --from osm " + kHelsinki +
                                " --center 60.169816,24.937947 --size 300x300 --ues 20 "
                                "--ue-groups 1 --uavs 3 --seed 756589 --out " +
                                dir.File("crop.json")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json uavs = nlohmann::json::parse(ReadFile(dir.File("crop.json")))["uavs"];
  ASSERT_EQ(uavs.size(), 3u);
  for (std::size_t u = 1; u < uavs.size(); ++u) {
    EXPECT_EQ(uavs[u]["position"][0].get<double>() - uavs[u - 1]["position"][0].get<double>(), 5.0);
    EXPECT_EQ(uavs[u]["position"][1], uavs[0]["position"][1]);
  }
}

TEST(RlposSimImport, BadPlaceInputIsOneLineAndWritesNothing) {
  TempDir dir;
  ExpectRejected(dir, "--from osm " + dir.File("missing.osm.pbf") + kSquare,
                 dir.File("missing.osm.pbf") + ": cannot open: No such file or directory");
  ExpectRejected(dir, "--from osm " + kHelsinki + " --center 10,10 --size 100x100",
                 "rlpos-sim: error: --center: the venue's centre 10,10 is outside the data");
  ExpectRejected(dir, "--from osm " + kHelsinki,
                 "rlpos-sim: error: --center: the venue needs --center LAT,LON with --size WxD");
  ExpectRejected(dir, "--from osm " + kHelsinki + " --center 60.1697,24.9505 --size 150 --ues 0",
                 "rlpos-sim: error: --ues: expected 1 to 100 UEs, got 0");
  ExpectRejected(dir, "--from geojson " + kHelsinki + kSquare,
                 "rlpos-sim: error: --from: \"geojson\" does not read an OpenStreetMap file");
}

TEST(RlposSimImport, BadInputIsOneLineAndWritesNothing) {
  TempDir dir;
  WriteFile(dir.File("malformed.json"), "{\"Gym\": {");
  ExpectRejected(dir, "--from rlpos3 " + dir.File("malformed.json"),
                 dir.File("malformed.json") + ": /: malformed JSON at line 1");
  ExpectRejected(dir, "--from rlpos3 " + dir.File("missing.json"),
                 dir.File("missing.json") + ": cannot open: No such file or directory");
  ExpectRejected(dir, "--from rlpos2 " + kFull,
                 "rlpos-sim: error: --from: unknown format \"rlpos2\" (known: rlpos3, osm, "
                 "geojson)");
  ExpectRejected(dir, "--from rlpos3 " + Edited(dir, "del c[\"Gym\"][\"venueSize\"][\"Ymax\"]"),
                 "edited.json: /Gym/venueSize/Ymax: is required (a number)");
  ExpectRejected(dir,
                 "--from rlpos3 " + Edited(dir,
                                           "c[\"ns3Sim\"][\"defaultValues\"][\"Buildings\"][2]["
                                           "\"BuildingPosition\"][0] = 9"),
                 "/ns3Sim/defaultValues/Buildings/2/BuildingPosition: xmin (9) must be below "
                 "xmax (5)");
  ExpectRejected(dir,
                 "--from rlpos3 " + Edited(dir,
                                           "c[\"ns3Sim\"][\"defaultValues\"][\"UENodes\"][0]["
                                           "\"positionVector\"] = [-35, 20, 1.5]"),
                 "/ns3Sim/defaultValues/UENodes/0/positionVector: UE at (-35, 20, 1.5) is inside "
                 "the building /ns3Sim/defaultValues/Buildings/0");
  ExpectRejected(
      dir,
      "--from rlpos3 " +
          Edited(dir,
                 "c[\"ns3Sim\"][\"defaultValues\"][\"UENodes\"][3][\"DataRate\"] = \"-1Gbps\""),
      "/ns3Sim/defaultValues/UENodes/3/DataRate: negative data rate \"-1Gbps\"");
}

// ns-3's own checks run before anything is written, and name the source's field.
TEST(RlposSimImport, Ns3ChecksNameTheSourceField) {
  TempDir dir;
  ExpectRejected(
      dir,
      "--from rlpos3 " +
          Edited(dir, "c[\"ns3Sim\"][\"defaultValues\"][\"wifiChannelNumber\"] = 36"),
      "/ns3Sim/defaultValues/wifiChannelNumber: channel 36 is not a 80 MHz 802.11ac channel");
}

}  // namespace
}  // namespace rlpos::testing
