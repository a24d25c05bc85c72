#include "worker/learning/policy_folder/general_placement.h"

#include <stdexcept>

#include "common/config/config_error.h"
#include "common/scenario/scenario_contradiction.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent_base/greedy_flight.h"
#include "worker/learning/agent_base/ppo_greedy_policy.h"
#include "worker/learning/agent_base/trainer.h"

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

namespace {

std::shared_ptr<PpoGreedyPolicy> LoadedPolicy(const PolicyFolder& folder, const Env& env) {
  if (!FliesWithoutLibtorch(folder))
    throw std::invalid_argument(folder.dir + " is not a general PPO policy");
  auto policy = std::make_shared<PpoGreedyPolicy>(folder.trained.agent,
                                                  static_cast<int>(env.ObservationSpace().Dim()),
                                                  env.ActionSpace().n, env.UeSlots());
  policy->Load(folder.dir);
  return policy;
}

}  // namespace

Placement GeneralPlacement(const PolicyFolder& folder, const CommonOptions& options) {
  UavPositioningEnv env(GeneralTarget(folder, options));
  const std::shared_ptr<PpoGreedyPolicy> policy = LoadedPolicy(folder, env);
  return FlyGeneralPlacement(env, *policy, folder.eval_run,
                             GreedyEpisodeOptions(folder.trained.agent))
      .final_info.positions;
}

TrackDecision TrackWith(const Scenario& target, std::shared_ptr<Agent> agent, std::uint64_t run) {
  const EpisodeOptions greedy = GreedyEpisodeOptions(target.agent);
  return [target, agent, run, greedy](const std::vector<Vec3>& ue_positions,
                                      const Placement& uavs_now) {
    // The scenario of this moment: its UEs standing where they are, its UAVs starting where
    // they are (the first decision: the baseline, as `position` flies it).
    Scenario now = target;
    for (std::size_t i = 0; i < ue_positions.size() && i < now.ues.size(); ++i) {
      now.ues[i].position = ue_positions[i];
      now.ues[i].mobility = MobilitySpec{};
    }
    for (std::size_t u = 0; u < uavs_now.size() && u < now.uavs.size(); ++u)
      now.uavs[u].initial = uavs_now[u];
    UavPositioningEnv env(now);
    return FlyGreedyToBest(env, *agent, run, greedy, kGeneralPatienceSteps).final_info.positions;
  };
}

TrackDecision GeneralTrack(const PolicyFolder& folder, const CommonOptions& options) {
  const Scenario target = GeneralTarget(folder, options, true);
  UavPositioningEnv first(target);
  return TrackWith(target, LoadedPolicy(folder, first), folder.eval_run);
}

}  // namespace rlpos::sim
