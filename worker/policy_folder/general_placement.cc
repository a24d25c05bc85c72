#include "worker/policy_folder/general_placement.h"

#include <stdexcept>

#include "common/config/config_error.h"
#include "common/scenario/scenario_contradiction.h"
#include "worker/agent/greedy_flight.h"
#include "worker/agent/ppo_greedy_policy.h"
#include "worker/agent/trainer.h"
#include "worker/environment/scenario_loading.h"
#include "worker/uav_env/uav_positioning_env.h"

namespace rlpos::sim {

Scenario GeneralTarget(const PolicyFolder& folder, const CommonOptions& options,
                       bool run_decides_interval) {
  Scenario target = LoadScenarioFor(options, {});
  const int uavs = static_cast<int>(target.uavs.size());
  if (uavs < folder.scope.min_uavs || uavs > folder.scope.max_uavs) {
    const std::string trained =
        folder.scope.min_uavs == folder.scope.max_uavs
            ? std::to_string(folder.scope.min_uavs)
            : std::to_string(folder.scope.min_uavs) + "-" + std::to_string(folder.scope.max_uavs);
    throw ConfigError("--policy", folder.dir + " was trained for " + trained + " UAV(s); " +
                                      options.scenario_file + " has " + std::to_string(uavs));
  }
  const double run_interval = target.env.decision_interval;
  target.env = folder.trained.env;
  target.agent = folder.trained.agent;
  Scenario checked = target;
  if (run_decides_interval)
    checked.env.decision_interval = run_interval;
  const auto contradiction =
      FirstContradiction(checked, ScenarioDocument(options.scenario_file, options.overrides));
  if (contradiction) {
    throw ConfigError("--policy", folder.dir + " (a policy for any scenario) does not fit " +
                                      options.scenario_file + ": " + contradiction->path + ": " +
                                      contradiction->problem);
  }
  return target;
}

bool FliesWithoutLibtorch(const PolicyFolder& folder) {
  return folder.scope.general && !folder.torchscript && folder.trained.agent.algorithm == "ppo";
}

Placement GeneralPlacement(const PolicyFolder& folder, const CommonOptions& options) {
  if (!FliesWithoutLibtorch(folder))
    throw std::invalid_argument(folder.dir + " is not a general PPO policy");
  UavPositioningEnv env(GeneralTarget(folder, options));
  PpoGreedyPolicy policy(folder.trained.agent, static_cast<int>(env.ObservationSpace().Dim()),
                         env.ActionSpace().n, env.UeSlots());
  policy.Load(folder.dir);
  return FlyGreedy(env, policy, folder.eval_run, GreedyEpisodeOptions(folder.trained.agent))
      .final_info.positions;
}

}  // namespace rlpos::sim
