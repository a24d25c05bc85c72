#pragma once
// SAC's hyperparameters (twin Q, tanh-squashed Gaussian policy, automatic temperature):
// declared once here, read by worker/learning/agent/sac_agent.cc. Defaults: Haarnoja et al. 2018 /
// CleanRL's sac_continuous_action.py, except the warm-up (1,000 random steps, not 5,000: half
// of a 10,000-step training would be random). The replay's capacity is its own
// (agent.sac.replay_capacity), not DQN's.
#include <cstdint>
#include <optional>

#include "common/config/setting.h"

namespace rlpos {

struct SacSpec {
  double policy_learning_rate = 1e-3;
  double q_learning_rate = 1e-3;
  double gamma = 0.99;
  double tau = 0.005;
  int batch_size = 256;
  std::int64_t replay_capacity = 1000000;
  int warmup_steps = 1000;
  int update_interval = 1;
  std::optional<double> alpha;
};

inline const SettingsTable<SacSpec>& SacHyperparameters() {
  static const SettingsTable<SacSpec> table{
      "sac",
      "/agent/sac",
      "SAC on the continuous displacements (env.action_space \"continuous\"); CleanRL's "
      "sac_continuous_action.py values where they differ.",
      {{"policy_learning_rate", &SacSpec::policy_learning_rate, PositiveAtMost(1.0),
        "Adam, the policy's. CleanRL: 3e-4"},
       {"q_learning_rate", &SacSpec::q_learning_rate, PositiveAtMost(1.0),
        "Adam, the Q-networks' and the temperature's. CleanRL: 1e-3"},
       {"gamma", &SacSpec::gamma, Between(0.0, 1.0), "discount"},
       {"tau", &SacSpec::tau, PositiveAtMost(1.0), "Polyak averaging of the target Q-networks"},
       {"batch_size", &SacSpec::batch_size, Integers(1, 65536), "transitions per update"},
       {"replay_capacity", &SacSpec::replay_capacity, Integers(1, 100000000),
        "transitions in the uniform replay. Unset, with agent.algorithm sac: agent.replay_capacity "
        "if the scenario sets that (SAC read DQN's key before it had its own)"},
       {"warmup_steps", &SacSpec::warmup_steps, Integers(0, 1000000000),
        "uniformly random actions before learning starts. CleanRL: 5000"},
       {"update_interval", &SacSpec::update_interval, Integers(1, 1000000),
        "env steps per gradient step"},
       {"alpha", &SacSpec::alpha, NonNegative(),
        "the entropy temperature; null: tuned automatically towards minus the action's "
        "dimension (CleanRL's autotune); a number fixes it"}}};
  return table;
}

}  // namespace rlpos
