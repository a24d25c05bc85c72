#include "worker/programs/rl_commands/torchscript_placement.h"

#include <memory>
#include <stdexcept>
#include <utility>

#include "common/config/config_error.h"
#include "worker/learning/agent/torchscript_policy.h"

namespace rlpos::sim {
namespace {

// The manifest's dims must be the spaces of the env its scenario.json makes.
void CheckDim(const PolicyFolder& folder, const char* key, int declared, int env_has,
              const std::string& what) {
  if (declared != env_has) {
    throw ConfigError("--policy", folder.dir + "/" + kTorchScriptManifestFile + ": /" + key + ": " +
                                      std::to_string(declared) + ", but scenario.json's env has " +
                                      std::to_string(env_has) + " " + what);
  }
}

std::string Join(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names)
    text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace

Placement TorchScriptPlacement(const PolicyFolder& folder, UavPositioningEnv& env) {
  const TorchScriptManifest& m = *folder.torchscript;
  const BoxSpace observations = env.ObservationSpace();
  CheckDim(folder, "observation_dim", m.observation_dim, static_cast<int>(observations.Dim()),
           "observations (" + Join(folder.trained.env.observations) + ")");
  CheckDim(folder, "action_count", m.action_count, env.ActionSpace().n,
           "actions (" + Join(folder.trained.env.actions) + ")");
  const std::string model = folder.dir + "/" + kTorchScriptModelFile;
  // The policy's problems are the model file's; the env's own errors pass as they are.
  std::unique_ptr<TorchScriptPolicy> policy;
  try {
    policy = std::make_unique<TorchScriptPolicy>(model, m.observation_dim, m.action_count);
  } catch (const std::invalid_argument& e) {
    throw ConfigError("--policy", model + ": " + e.what());
  }
  // The observation exactly as the Python binding gave it in training.
  const Float32Clip clip(observations);
  std::vector<double> observation = env.Reset(m.eval_run);
  for (int step = 1;; ++step) {
    int action = 0;
    try {
      action = policy->GreedyAction(clip(observation), env.ValidActions());
    } catch (const std::invalid_argument& e) {
      throw ConfigError("--policy", model + ": at step " + std::to_string(step) + ": " + e.what());
    }
    StepResult r = env.Step(action);
    if (r.terminated || r.truncated)
      break;
    observation = std::move(r.observation);
  }
  return env.LastInfo().positions;
}

}  // namespace rlpos::sim
