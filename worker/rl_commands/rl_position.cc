#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "worker/agent/make_agent.h"
#include "worker/agent/torch_threads.h"
#include "worker/agent/trainer.h"
#include "worker/rl_commands/rl_commands.h"
#include "worker/sim_api/rl_plugin_api.h"
#include "worker/uav_env/uav_positioning_env.h"

namespace rlpos::sim {

Placement PolicyPlacement(const Scenario& scenario, const std::string& policy) {
  Scenario s = scenario;
  if (policy.empty())
    throw ConfigError("--policy", "is required for the rl positioner");
  nlohmann::json trained;
  try {
    trained = ReadJsonFile(policy + "/result.json");
  } catch (const ConfigError& e) {
    throw ConfigError("--policy", policy + "/result.json: " + e.problem());
  }
  // The policy says what it is: its algorithm, and the action space and fidelity it was trained in.
  s.env.fidelity = trained.value("fidelity", s.env.fidelity);
  s.agent.algorithm = trained.value("algorithm", std::string("dqn"));
  s.env.action_space = trained.value("action_space", std::string("discrete"));
  if ((s.agent.algorithm != "dqn" && s.agent.algorithm != "ppo" && s.agent.algorithm != "sac") ||
      (s.env.action_space != "discrete" && s.env.action_space != "continuous")) {
    throw ConfigError("--policy", policy + "/result.json: unknown algorithm or action_space");
  }
  UavPositioningEnv env(s);
  const std::unique_ptr<Agent> agent = MakeAgent(s.agent, env);
  agent->Load(policy);
  const std::uint64_t run =
      trained.value("first_episode_run", 1ULL) + static_cast<std::uint64_t>(s.agent.train_episodes);
  return RunEpisode(env, *agent, run, false).final_info.positions;
}

}  // namespace rlpos::sim

extern "C" const rlpos::sim::RlCommands* rlpos_rl_commands_v2() {
  // rlpos-sim asks for the commands before it trains or loads a policy: the moment to size
  // libtorch's pool.
  rlpos::UseOneTorchThreadUnlessAsked();
  static const rlpos::sim::RlCommands commands{rlpos::sim::TrainCommand,
                                               rlpos::sim::PolicyPlacement};
  return &commands;
}
