#pragma once
// The RL commands (train, the rl positioner) live in a module loaded on demand, so that
// validate and eval, which a campaign runs hundreds of times, never load libtorch: its
// start-up alone costs more than 0.5 s per process.
#include <functional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/programs/sim_api/sim_options.h"

namespace rlpos::sim {

// One decision of a run in which the UEs move: the UAVs' targets with the UEs at `ue_positions`
// (one per UE) and the UAVs at `uavs_now`.
using TrackDecision =
    std::function<Placement(const std::vector<Vec3>& ue_positions, const Placement& uavs_now)>;

struct RlCommands {
  int (*train)(const CommonOptions& options, const TrainOptions& train);
  Placement (*policy_placement)(const CommonOptions& options, const std::string& policy);
  // A policy for any scenario flown online (rlpos-sim track --positioner rl): each decision
  // flies it greedy from where the UAVs are, the UEs where they are, and gives where it ends.
  TrackDecision (*policy_track)(const CommonOptions& options, const std::string& policy);
};

}  // namespace rlpos::sim

// The module's one entry point (looked up by name with dlsym).
extern "C" const rlpos::sim::RlCommands* rlpos_rl_commands_v5();
