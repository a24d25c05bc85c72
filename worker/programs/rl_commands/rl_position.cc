#include "common/config/config_error.h"
#include "common/scenario/scenario_contradiction.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/make_agent.h"
#include "worker/learning/agent/torch_threads.h"
#include "worker/learning/agent_base/greedy_flight.h"
#include "worker/learning/agent_base/trainer.h"
#include "worker/learning/policy_folder/general_placement.h"
#include "worker/learning/policy_folder/policy_folder.h"
#include "worker/programs/rl_commands/rl_commands.h"
#include "worker/programs/rl_commands/torchscript_placement.h"
#include "worker/programs/sim_api/rl_plugin_api.h"

namespace rlpos::sim {
namespace {

// A policy knows only the MDP it was trained in: the caller's scenario may restate it, not
// change it.
void RefuseContradiction(const PolicyFolder& folder, const CommonOptions& options) {
  const auto contradiction = FirstContradiction(
      folder.trained, ScenarioDocument(options.scenario_file, options.overrides));
  if (contradiction) {
    throw ConfigError("--policy", folder.dir + " (trained on " + folder.trained.name +
                                      ") does not fit " + options.scenario_file + ": " +
                                      contradiction->path + ": " + contradiction->problem);
  }
}

}  // namespace

Placement PolicyPlacement(const CommonOptions& options, const std::string& policy) {
  if (policy.empty())
    throw ConfigError("--policy", "is required for the rl positioner");
  const PolicyFolder folder = ReadPolicyFolder(policy);
  if (FliesWithoutLibtorch(folder))
    return GeneralPlacement(folder, options);
  if (folder.scope.general && !folder.torchscript) {
    UavPositioningEnv env(GeneralTarget(folder, options));
    const std::unique_ptr<Agent> agent = MakeAgent(folder.trained.agent, env);
    agent->Load(policy);
    return FlyGeneralPlacement(env, *agent, folder.eval_run,
                               GreedyEpisodeOptions(folder.trained.agent))
        .final_info.positions;
  }
  RefuseContradiction(folder, options);
  // Training's own final evaluation episode: its scenario (fidelity and agent included), its
  // run, from the baseline, greedy. A TorchScript policy flies in its scenario's env the same way.
  UavPositioningEnv env(folder.trained);
  if (folder.torchscript)
    return TorchScriptPlacement(folder, env);
  const std::unique_ptr<Agent> agent = MakeAgent(folder.trained.agent, env);
  agent->Load(policy);
  return FlyGreedy(env, *agent, folder.eval_run, GreedyEpisodeOptions(folder.trained.agent))
      .final_info.positions;
}

TrackDecision PolicyTrack(const CommonOptions& options, const std::string& policy) {
  if (policy.empty())
    throw ConfigError("--policy", "is required for the rl positioner");
  const PolicyFolder folder = ReadPolicyFolder(policy);
  if (!folder.scope.general || folder.torchscript) {
    throw ConfigError("--policy",
                      folder.dir +
                          " is not a policy for any scenario: as the UEs move, the "
                          "scenario changes; train one with rlpos-sim train --generated");
  }
  if (FliesWithoutLibtorch(folder))
    return GeneralTrack(folder, options);
  const Scenario target = GeneralTarget(folder, options, true);
  UavPositioningEnv first(target);
  std::shared_ptr<Agent> agent = MakeAgent(target.agent, first);
  agent->Load(policy);
  return TrackWith(target, agent, folder.eval_run);
}

}  // namespace rlpos::sim

extern "C" const rlpos::sim::RlCommands* rlpos_rl_commands_v5() {
  // rlpos-sim asks for the commands before it trains or loads a policy: the moment to size
  // libtorch's pool.
  rlpos::UseOneTorchThreadUnlessAsked();
  static const rlpos::sim::RlCommands commands{
      rlpos::sim::TrainCommand, rlpos::sim::PolicyPlacement, rlpos::sim::PolicyTrack};
  return &commands;
}
