#pragma once
// A policy folder as `rlpos-sim train` writes it, read back as what an exact replay of the
// training's own final evaluation needs: the scenario as trained (its overrides, the agent's
// hyperparameters and the fidelity included: scenario.json) and the seed stream (result.json).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos::sim {

struct PolicyFolder {
  std::string dir;
  Scenario trained;                     // scenario.json
  std::uint64_t first_episode_run = 0;  // RngRun of the first training episode
  std::uint64_t eval_run =
      0;  // RngRun of the final evaluation episode, whose end result.json reports
  // A general policy may be placed in scenarios other than its own. None is yet: the field is
  // read so that a folder that claims it is refused rather than misread.
  bool general = false;
};

// The seed stream's fields of result.json.
nlohmann::json SeedStreamJson(std::uint64_t first_episode_run, std::uint64_t eval_run);

// Reads DIR/scenario.json and DIR/result.json (folders from before eval_run existed: it is the
// run training gave its last evaluation episode). Bad or missing files: ConfigError on --policy.
PolicyFolder ReadPolicyFolder(const std::string& dir);

}  // namespace rlpos::sim
