#include "common/scenario/default_sets.h"

#include <stdexcept>

namespace rlpos {
namespace {

// The network, batch and horizon that a policy trained across many scenarios needs (docs/
// any-scenario.md, "A policy for any scenario"), after PPO's own set.
std::vector<std::string> AnyScenario(const char* observations) {
  return {"agent.algorithm=ppo",         "env.action_space=discrete",
          "env.fidelity=analytic",       std::string("env.observations=") + observations,
          "agent.hidden=[128,128]",      "agent.ppo.num_envs=16",
          "agent.ppo.gamma=0.95",        "agent.ppo.epochs=4",
          "agent.train_episode_steps=40"};
}

}  // namespace

const std::vector<DefaultSet>& DefaultSets() {
  static const std::vector<DefaultSet> sets{
      {"dqn",
       "--algorithm dqn, a campaign's dqn train jobs: DQN on the moves",
       {"agent.algorithm=dqn", "env.action_space=discrete"}},
      {"ppo",
       "--algorithm ppo, a campaign's ppo train jobs: PPO on the moves",
       {"agent.algorithm=ppo", "env.action_space=discrete"}},
      {"sac",
       "--algorithm sac, a campaign's sac train jobs: SAC on displacements",
       {"agent.algorithm=sac", "env.action_space=continuous"}},
      {"any-scenario",
       "train --generated or --scenarios with one UAV: PPO at analytic fidelity on the "
       "observations that mean the same in every scenario",
       AnyScenario(R"(["zone","ues","heights","coverage","lookahead"])")},
      {"any-scenario-several",
       "the same where the training draws several UAVs: each also sees the others",
       AnyScenario(R"(["zone","ues","heights","coverage","lookahead","others"])")},
  };
  return sets;
}

const DefaultSet& DefaultSetNamed(const std::string& name) {
  std::string known;
  for (const DefaultSet& set : DefaultSets()) {
    if (set.name == name)
      return set;
    known += (known.empty() ? "" : ", ") + set.name;
  }
  throw std::invalid_argument("no default set \"" + name + "\" (known: " + known + ")");
}

const DefaultSet& AlgorithmDefaults(const std::string& algorithm) {
  return DefaultSetNamed(algorithm);
}

const DefaultSet& AnyScenarioDefaults(int max_uavs) {
  return DefaultSetNamed(max_uavs > 1 ? "any-scenario-several" : "any-scenario");
}

}  // namespace rlpos
