// rlpos-sim render as a user runs it: a PNG or an SVG of the scenario, the same bytes each time,
// the placement from --position, --result or --placement, and one-line errors that leave no
// file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/command.h"
#include "tests/support/temp_dir.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

std::string Render(const std::string& args) {
  return BuiltBinary("rlpos-sim") + " render " + args;
}

std::string ReadBytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

class RenderCli : public ::testing::Test {
 protected:
  // A failure: exit code, one line naming `fragment` on stderr, nothing on stdout, no map.
  void ExpectRefused(const std::string& args, int exit_code, const std::string& fragment) {
    const CommandResult r = RunCommand(Render(args));
    EXPECT_EQ(r.exit_code, exit_code) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.find("rlpos-sim: error: "), 0u) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    for (const auto& entry : fs::directory_iterator(dir_.path()))
      ADD_FAILURE() << "left behind: " << entry.path();
  }
  TempDir dir_;
};

TEST_F(RenderCli, PngAndSvgOfTheBaseline) {
  const std::string png = dir_.File("c.png"), svg = dir_.File("c.svg");
  const CommandResult r = RunCommand(Render(kScenarios + "c.json --side --out " + png));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, png + "\n");
  EXPECT_EQ(ReadBytes(png).substr(0, 8), "\x89PNG\r\n\x1a\n");
  ASSERT_EQ(RunCommand(Render(kScenarios + "c.json --out " + svg)).exit_code, 0);
  EXPECT_EQ(ReadBytes(svg).rfind("<?xml", 0), 0u);
}

TEST_F(RenderCli, SameInputsSameBytes) {
  for (const char* ext : {".svg", ".png"}) {
    const std::string a = dir_.File(std::string("a") + ext), b = dir_.File(std::string("b") + ext);
    const std::string args = kScenarios + "urban3.json --side --out ";
    ASSERT_EQ(RunCommand(Render(args + a)).exit_code, 0);
    ASSERT_EQ(RunCommand(Render(args + b)).exit_code, 0);
    EXPECT_TRUE(ReadBytes(a) == ReadBytes(b)) << ext;
  }
}

TEST_F(RenderCli, PlacementFromThePositionCommandsJson) {
  const std::string result = dir_.File("centroid.json");
  ASSERT_EQ(RunCommand(Sim("position --scenario " + kScenarios +
                           "campus2.json --positioner centroid --json > " + result))
                .exit_code,
            0);
  const std::string out = dir_.File("m.svg");
  const CommandResult r =
      RunCommand(Render(kScenarios + "campus2.json --result " + result + " --out " + out));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Another scenario's result is refused.
  fs::remove(out);
  fs::rename(result, dir_.File("centroid.json.keep"));
  const std::string moved = dir_.File("centroid.json.keep");
  const CommandResult other =
      RunCommand(Render(kScenarios + "c.json --result " + moved + " --out " + out));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("is a result of scenario campus2, not C"), std::string::npos)
      << other.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(RenderCli, SeveralPlacementsAndAFlight) {
  const std::string trajectory = dir_.File("trajectory.csv");
  std::ofstream(trajectory) << "episode,step,uav,action,x,y,z,n_los,throughput_mbps,reward\n"
                               "3,1,0,right,55,50,25,1,1,0\n3,2,0,backward,55,45,25,1,1,0\n";
  const std::string out = dir_.File("m.png");
  const CommandResult r =
      RunCommand(Render(kScenarios +
                        "b.json --placement baseline=50,50,25 --placement 'rl@seed2=55,45,25' "
                        "--trajectory " +
                        trajectory + " --out " + out));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  fs::remove(out);
  fs::remove(trajectory);
}

TEST_F(RenderCli, BadInputsAreOneLineErrorsAndLeaveNoFile) {
  const std::string c = kScenarios + "c.json";
  const std::string out = " --out " + dir_.File("m.png");
  ExpectRefused(dir_.File("none.json") + out, 2,
                "none.json: cannot open: No such file or directory");
  ExpectRefused(
      c + " --out " + dir_.File("m.jpg"), 2,
      "--out: \"" + dir_.File("m.jpg") + "\": the map's file name must end in .png or .svg");
  ExpectRefused(c + " --position 50,50" + out, 2, "--position: expected x,y,z in metres");
  ExpectRefused(c + " --position 150,50,20" + out, 2,
                "--position: (150, 50, 20) is outside the venue");
  ExpectRefused(c + " --position 50,50,10" + out, 2, "is inside building 0 (\"tower\")");
  ExpectRefused(c + " --result " + dir_.File("none.json") + out, 2, "--result: ");
  ExpectRefused(c + " --trajectory " + dir_.File("none.csv") + out, 2,
                "--trajectory: " + dir_.File("none.csv") + ": cannot open file");
  ExpectRefused(c + " --placement oracle" + out, 2, "--placement: expected LABEL=x,y,z");
  ExpectRefused(c + " --placement oracle=50,50,10" + out, 2,
                "--placement oracle: (50, 50, 10) is inside building 0");
  ExpectRefused(c + " --out " + dir_.File("no/such/folder/m.png"), 1, "no/such/folder");
}

}  // namespace
}  // namespace rlpos::testing
