#pragma once
// A policy folder read back as what an exact replay needs, in one of two formats:
// - ours, as `rlpos-sim train` writes it: the scenario as trained (its overrides, the agent's
//   hyperparameters and the fidelity included: scenario.json), the seed stream (result.json) and
//   the agent's networks;
// - TorchScript, trained anywhere: policy.json (torchscript_manifest.h), scenario.json (the env
//   as trained) and model.pt.
// A folder with a policy.json is of the second.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/scenario/scenario.h"
#include "common/wire/general_policy.h"
#include "worker/learning/policy_folder/torchscript_manifest.h"

namespace rlpos::sim {

struct PolicyFolder {
  std::string dir;
  Scenario trained;                     // scenario.json
  std::uint64_t first_episode_run = 0;  // RngRun of the first training episode
  std::uint64_t eval_run =
      0;  // RngRun of the final evaluation episode, whose end result.json reports
  // A general policy (rlpos-sim train --generated or --scenarios) is placed in any scenario with
  // a UAV count in [scope.min_uavs, scope.max_uavs]: it flies there with its own env settings
  // (trained.env) from the baseline.
  GeneralPolicyScope scope;
  // Set for a TorchScript folder (model.pt is its policy); unset for ours (the agent of
  // trained.agent is).
  std::optional<TorchScriptManifest> torchscript;
};

// The seed stream's fields of result.json.
nlohmann::json SeedStreamJson(std::uint64_t first_episode_run, std::uint64_t eval_run);

// Reads DIR/scenario.json and DIR/result.json (folders from before eval_run existed: it is the
// run training gave its last evaluation episode), or for a TorchScript folder DIR/policy.json and
// DIR/scenario.json. Only these fixed names inside DIR are read. Bad or missing files:
// ConfigError on --policy.
PolicyFolder ReadPolicyFolder(const std::string& dir);

}  // namespace rlpos::sim
