#include "worker/learning/policy_folder/policy_folder.h"

#include <filesystem>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos::sim {
namespace {

constexpr const char* kFirstEpisodeRun = "first_episode_run";
constexpr const char* kEvalRun = "eval_run";
constexpr const char* kGeneral = "general";

nlohmann::json ReadFolderFile(const std::string& dir, const std::string& name) {
  try {
    return ReadJsonFile(dir + "/" + name);
  } catch (const ConfigError& e) {
    throw ConfigError("--policy", dir + "/" + name + ": " + e.problem());
  }
}

std::uint64_t Run(const nlohmann::json& result, const char* key, const std::string& dir) {
  const auto it = result.find(key);
  if (it == result.end() || !it->is_number_unsigned() || it->get<std::uint64_t>() == 0) {
    throw ConfigError("--policy", dir + "/result.json: /" + std::string(key) +
                                      ": expected a positive RngRun; retrain the policy");
  }
  return it->get<std::uint64_t>();
}

// result.json's algorithm, action space and fidelity must be scenario.json's: a folder whose
// two files disagree was not written by one training.
void CheckAgrees(const nlohmann::json& result, const char* key, const std::string& trained,
                 const std::string& dir) {
  const auto it = result.find(key);
  if (it != result.end() && *it != trained) {
    throw ConfigError("--policy", dir + "/result.json: /" + std::string(key) + ": " + it->dump() +
                                      ", but scenario.json says \"" + trained + "\"");
  }
}

Scenario ReadTrainedScenario(const std::string& dir) {
  try {
    return ParseScenario(ReadFolderFile(dir, "scenario.json"));
  } catch (const ConfigError& e) {
    if (e.path() == "--policy")
      throw;
    throw ConfigError("--policy", dir + "/scenario.json: " + e.describe());
  }
}

PolicyFolder ReadTorchScriptFolder(const std::string& dir) {
  PolicyFolder folder;
  folder.dir = dir;
  const std::string manifest = dir + "/" + kTorchScriptManifestFile;
  folder.torchscript =
      ParseTorchScriptManifest(ReadFolderFile(dir, kTorchScriptManifestFile), manifest);
  folder.trained = ReadTrainedScenario(dir);
  if (folder.trained.env.action_space != folder.torchscript->action_space) {
    throw ConfigError("--policy",
                      manifest + ": /action_space: \"" + folder.torchscript->action_space +
                          "\", but scenario.json says \"" + folder.trained.env.action_space + "\"");
  }
  folder.eval_run = folder.torchscript->eval_run;
  return folder;
}

}  // namespace

nlohmann::json SeedStreamJson(std::uint64_t first_episode_run, std::uint64_t eval_run) {
  return {{kFirstEpisodeRun, first_episode_run}, {kEvalRun, eval_run}, {kGeneral, false}};
}

PolicyFolder ReadPolicyFolder(const std::string& dir) {
  // A model.pt without its manifest is a TorchScript folder too, refused for the missing file.
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(fs::path(dir) / kTorchScriptManifestFile, ec) ||
      fs::exists(fs::path(dir) / kTorchScriptModelFile, ec))
    return ReadTorchScriptFolder(dir);
  PolicyFolder folder;
  folder.dir = dir;
  const nlohmann::json result = ReadFolderFile(dir, "result.json");
  folder.trained = ReadTrainedScenario(dir);
  const Scenario& s = folder.trained;
  CheckAgrees(result, "algorithm", s.agent.algorithm, dir);
  CheckAgrees(result, "action_space", s.env.action_space, dir);
  CheckAgrees(result, "fidelity", s.env.fidelity, dir);
  try {
    folder.scope = ReadGeneralPolicyScope(result);
  } catch (const std::invalid_argument& e) {
    throw ConfigError("--policy", dir + "/result.json: " + e.what());
  }
  folder.first_episode_run = Run(result, kFirstEpisodeRun, dir);
  folder.eval_run = result.contains(kEvalRun) ? Run(result, kEvalRun, dir)
                                              : EvaluationSeed(s.agent, folder.first_episode_run,
                                                               s.agent.eval_episodes - 1);
  return folder;
}

}  // namespace rlpos::sim
