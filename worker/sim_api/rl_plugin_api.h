#pragma once
// The RL commands (train, the rl positioner) live in a module loaded on demand, so that
// validate and eval, which a campaign runs hundreds of times, never load libtorch: its
// start-up alone costs more than 0.5 s per process.
#include <string>

#include "common/scenario/scenario.h"
#include "worker/sim_api/sim_options.h"

namespace rlpos::sim {

struct RlCommands {
  int (*train)(const CommonOptions& options, const TrainOptions& train);
  Placement (*policy_placement)(const CommonOptions& options, const std::string& policy);
};

}  // namespace rlpos::sim

// The module's one entry point (looked up by name with dlsym).
extern "C" const rlpos::sim::RlCommands* rlpos_rl_commands_v4();
