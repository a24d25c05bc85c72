#pragma once
// A policy for any scenario placed in the caller's scenario: the scenario it flies in (the
// caller's venue with the policy's own env and agent settings), and for ours, PPO's, the greedy
// flight itself, without libtorch (ppo_greedy_policy.h): what rlpos-sim and its RL module both
// place such a policy with.
#include <memory>
#include <string>

#include "common/scenario/scenario.h"
#include "worker/learning/agent_base/agent.h"
#include "worker/learning/policy_folder/policy_folder.h"
#include "worker/programs/sim_api/rl_plugin_api.h"
#include "worker/programs/sim_api/sim_options.h"

namespace rlpos::sim {

// The caller's scenario with the policy's env and agent settings: the caller may restate them,
// not change them (env.fidelity aside: it flies at its own). A run in which the UEs move (track)
// may set its own env.decision_interval (run_decides_interval): how often it asks the policy;
// each flight stays the policy's own episode. A UAV count outside the policy's scope or a
// contradiction: ConfigError on --policy.
Scenario GeneralTarget(const PolicyFolder& folder, const CommonOptions& options,
                       bool run_decides_interval = false);

// Whether GeneralPlacement flies `folder`: a general policy of ours (PPO's, as every one that
// rlpos-sim train --generated or --scenarios makes).
bool FliesWithoutLibtorch(const PolicyFolder& folder);

// The greedy flights of the policy in folder.dir in GeneralTarget's scenario: the best placement
// they reach (FlyGeneralPlacement: one flight from the baseline for one UAV, several from
// several starts for several UAVs).
// std::invalid_argument unless FliesWithoutLibtorch(folder); a policy.pt that is missing, damaged
// or of another shape: std::runtime_error naming it.
Placement GeneralPlacement(const PolicyFolder& folder, const CommonOptions& options);

// A run whose UEs move (rlpos-sim track) asks `agent` (a general policy, loaded) at each
// decision: a greedy flight of the policy's episode in `target` (GeneralTarget's, with
// run_decides_interval) as it is at that moment, from where the UAVs are, with RngRun `run`; the
// best placement it reaches (FlyGreedyToBest: one flight, so that the UAVs follow their UEs from
// where they are, even with several).
TrackDecision TrackWith(const Scenario& target, std::shared_ptr<Agent> agent, std::uint64_t run);

// TrackWith with the policy in folder.dir flown without libtorch; the errors of GeneralPlacement.
TrackDecision GeneralTrack(const PolicyFolder& folder, const CommonOptions& options);

}  // namespace rlpos::sim
