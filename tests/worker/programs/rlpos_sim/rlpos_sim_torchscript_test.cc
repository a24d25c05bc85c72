// A TorchScript policy folder (policy.json, scenario.json, model.pt) is flown by `position
// --positioner rl --policy DIR` greedily from the baseline, and every malformed or mismatched
// part of it is refused in one line before anything runs. The models are written by
// torchscript_fixtures.py with Debian's python3-torch.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command.h"
#include "tests/worker/programs/rlpos_sim/sim_test_support.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

// Scenario B's spaces: x, y, z, n_los; up, down, forward, backward, left, right, stay.
constexpr int kObservations = 4;
constexpr int kActions = 7;

class TorchScriptFolder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    models_ = fs::temp_directory_path() / ("rlpos-ts-models-" + std::to_string(::getpid()));
    fs::remove_all(models_);
    const auto r = RunCommand("/usr/bin/python3 " + std::string(RLPOS_SOURCE_DIR) +
                              "/tests/worker/programs/rlpos_sim/torchscript_fixtures.py " +
                              models_.string() + " " + std::to_string(kActions));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(models_); }

  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rlpos-ts-policy-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A folder as rlpos.save_torchscript_policy writes it: B (analytic) and a valid manifest.
  void WriteFolder(const std::string& model) {
    nlohmann::json scenario = nlohmann::json::parse(std::ifstream(kScenarioB));
    scenario["env"]["fidelity"] = "analytic";
    std::ofstream(dir_ / "scenario.json") << scenario.dump(2);
    WriteManifest(Manifest());
    fs::copy_file(models_ / (model + ".pt"), dir_ / "model.pt");
  }
  static nlohmann::json Manifest() {
    return {{"format", "torchscript"},    {"format_version", 1},
            {"action_space", "discrete"}, {"observation_dim", kObservations},
            {"action_count", kActions},   {"eval_run", 1}};
  }
  void WriteManifest(const nlohmann::json& manifest) {
    std::ofstream(dir_ / "policy.json") << manifest.dump(2);
  }

  CommandResult Position(const std::string& scenario = kScenarioB) {
    return RunCommand(Sim("position --scenario " + scenario + " --positioner rl --json --policy " +
                          dir_.string()));
  }
  nlohmann::json PlacedAt() {
    const auto r = Position();
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out)["position"] : nlohmann::json();
  }
  std::string ManifestFile() const { return (dir_ / "policy.json").string(); }
  std::string ModelFile() const { return (dir_ / "model.pt").string(); }

  static fs::path models_;
  fs::path dir_;
};

fs::path TorchScriptFolder::models_;

TEST_F(TorchScriptFolder, APolicyThatStaysHoldsTheBaseline) {
  WriteFolder("prefer_stay");
  EXPECT_EQ(PlacedAt(), nlohmann::json::array({50.0, 50.0, 25.0}));
}

TEST_F(TorchScriptFolder, TheGreedyMoveIsTheBestOfTheAllowedOnes) {
  // Up to B's ceiling (60 m); there up is masked, so right to the zone's edge (x 100); there
  // both are, so it stays. A plain argmax would keep asking for up, and hover at x 50.
  WriteFolder("prefer_up_right_stay");
  EXPECT_EQ(PlacedAt(), nlohmann::json::array({100.0, 50.0, 60.0}));
}

TEST_F(TorchScriptFolder, AScenarioThatContradictsTheFolderIsRefused) {
  WriteFolder("prefer_stay");
  ExpectOneLineRefusal(Position(kScenarios + "c.json"), dir_.string(),
                       "c.json: /ues/0/demand/mcs: 3 in the scenario, 0 in the policy");
}

TEST_F(TorchScriptFolder, AMissingOrMalformedManifestIsRefused) {
  WriteFolder("prefer_stay");
  fs::remove(dir_ / "policy.json");
  ExpectOneLineRefusal(Position(), ManifestFile(), "cannot open: No such file or directory");
  std::ofstream(dir_ / "policy.json") << "{\"format\": \"torchscript\",";
  ExpectOneLineRefusal(Position(), ManifestFile(), "line 1");
  WriteManifest(nlohmann::json::array());
  ExpectOneLineRefusal(Position(), ManifestFile(), "expected a JSON object");
}

TEST_F(TorchScriptFolder, EachBadManifestFieldIsNamed) {
  WriteFolder("prefer_stay");
  struct Case {
    const char* key;
    nlohmann::json value;  // null: the key removed
    const char* problem;
  };
  const Case cases[] = {
      {"format", "onnx", "/format: unknown format \"onnx\""},
      {"format_version", 2, "/format_version: unknown version 2"},
      {"action_space", "continuous", "/action_space: continuous actions are not supported"},
      {"action_space", "box", "/action_space: expected \"discrete\""},
      {"observation_dim", 0, "/observation_dim: expected an integer in [1, "},
      {"action_count", "7", "/action_count: expected an integer in [1, "},
      {"eval_run", nullptr, "/eval_run: missing"},
      {"temperature", 0.5, "/temperature: unknown key"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.key);
    nlohmann::json manifest = Manifest();
    if (c.value.is_null())
      manifest.erase(c.key);
    else
      manifest[c.key] = c.value;
    WriteManifest(manifest);
    ExpectOneLineRefusal(Position(), ManifestFile(), c.problem);
  }
}

TEST_F(TorchScriptFolder, DimsThatAreNotTheScenariosSpacesAreRefused) {
  WriteFolder("prefer_stay");
  nlohmann::json manifest = Manifest();
  manifest["observation_dim"] = 5;
  WriteManifest(manifest);
  ExpectOneLineRefusal(Position(), ManifestFile(),
                       "/observation_dim: 5, but scenario.json's env has 4 observations (x, y, "
                       "z, n_los)");
  manifest = Manifest();
  manifest["action_count"] = 6;
  WriteManifest(manifest);
  ExpectOneLineRefusal(Position(), ManifestFile(),
                       "/action_count: 6, but scenario.json's env has 7 actions");
  // Trained with continuous actions, declared discrete.
  WriteManifest(Manifest());
  nlohmann::json scenario = nlohmann::json::parse(std::ifstream(dir_ / "scenario.json"));
  scenario["env"]["action_space"] = "continuous";
  scenario["agent"]["algorithm"] = "sac";
  std::ofstream(dir_ / "scenario.json", std::ios::trunc) << scenario.dump(2);
  ExpectOneLineRefusal(Position(), ManifestFile(),
                       "/action_space: \"discrete\", but scenario.json says \"continuous\"");
}

TEST_F(TorchScriptFolder, AModelThatDoesNotLoadIsRefused) {
  WriteFolder("prefer_stay");
  std::ofstream(dir_ / "model.pt", std::ios::trunc) << "not a TorchScript archive";
  ExpectOneLineRefusal(Position(), ModelFile(), "does not load as a TorchScript module");
  fs::remove(dir_ / "model.pt");
  ExpectOneLineRefusal(Position(), ModelFile(), "does not load as a TorchScript module");
}

TEST_F(TorchScriptFolder, AModelOfTheWrongOutputIsRefusedBeforeFlying) {
  WriteFolder("wide");
  ExpectOneLineRefusal(Position(), ModelFile(),
                       "forward returns float [1, 8], expected [1, 7] float logits");
  fs::remove(dir_ / "model.pt");
  fs::copy_file(models_ / "pair.pt", dir_ / "model.pt");
  ExpectOneLineRefusal(Position(), ModelFile(), "forward returns a Tuple, expected [1, 7]");
}

TEST_F(TorchScriptFolder, NanLogitsAreRefused) {
  WriteFolder("nan");
  ExpectOneLineRefusal(Position(), ModelFile(), ": forward returns NaN logits");
  // Finite on the zero observation, NaN on the first one flown.
  fs::remove(dir_ / "model.pt");
  fs::copy_file(models_ / "nan_in_flight.pt", dir_ / "model.pt");
  ExpectOneLineRefusal(Position(), ModelFile(), ": at step 1: forward returns NaN logits");
}

}  // namespace
}  // namespace rlpos::testing
