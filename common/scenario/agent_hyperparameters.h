#pragma once
// The hyperparameters every algorithm shares (training length, checkpoints, seed, reward
// standardisation): declared once here, read by worker/agent and worker/sim/train_command.cc.
// Their keys sit in the scenario's "agent" object.
#include <cstdint>

#include "common/config/config_error.h"
#include "common/scenario/hyperparameter.h"

namespace rlpos {

struct AgentCommonSpec {
  bool normalise_rewards = true;
  int train_episodes = 10;
  int train_episode_steps = 0;
  bool exploring_starts = false;
  int eval_episodes = 1;
  int eval_interval = 0;
  int early_stop_checkpoints = 0;
  std::uint64_t seed = 1;
};

inline void CheckAgentCommonSpec(const AgentCommonSpec& a, const ObjectReader& reader) {
  if (a.early_stop_checkpoints > 0 && a.eval_interval == 0)
    throw ConfigError(reader.PathOf("early_stop_checkpoints"),
                      "needs checkpoints: set agent.eval_interval > 0");
}

inline const HyperparameterTable<AgentCommonSpec>& AgentCommonHyperparameters() {
  static const HyperparameterTable<AgentCommonSpec> table{
      "agent",
      "/agent",
      "Every algorithm's: training length, checkpoints, seed.",
      {{"normalise_rewards", &AgentCommonSpec::normalise_rewards, NoRange(),
        "TD targets (and PPO's and SAC's) use rewards standardised by the running mean and "
        "standard deviation of the rewards seen so far. Not in the paper. The greedy policy of "
        "an env that never terminates (ours) is unchanged by it, but the network no longer has "
        "to resolve 1 % differences (scenario A) on top of a large constant"},
       {"train_episodes", &AgentCommonSpec::train_episodes, Integers(1, 1000000),
        "training episodes"},
       {"train_episode_steps", &AgentCommonSpec::train_episode_steps, Integers(0, 1000000),
        "a training episode ends (truncated, as Gymnasium's max_episode_steps) after this many "
        "steps; checkpoints and the evaluation fly the env's whole episode. 0: the env's "
        "episode (env.episode_duration / env.decision_interval steps)"},
       {"exploring_starts", &AgentCommonSpec::exploring_starts, NoRange(),
        "each training episode starts every UAV at a point of its zone drawn from the episode's "
        "seed, on the lattice of env.step moves through its baseline; checkpoints and the "
        "evaluation start from the baseline. The policy then learns the whole zone, not only "
        "the cells on its way from the baseline, and finds a better region it would not fly "
        "through (Sutton and Barto's exploring starts)"},
       {"eval_episodes", &AgentCommonSpec::eval_episodes, Integers(1, 1000000),
        "greedy evaluation episodes after training"},
       {"eval_interval", &AgentCommonSpec::eval_interval, Integers(0, 1000000),
        "every this many training episodes, and after the last, a greedy checkpoint episode "
        "from the evaluation's seed scores the policy by its final reward; the best-scoring "
        "policy (the latest of equals) is kept, evaluated and saved (as Stable-Baselines3's "
        "EvalCallback keeps best_model). 0: the last policy. Each checkpoint costs one episode "
        "(at packet level, a full simulation)"},
       {"early_stop_checkpoints", &AgentCommonSpec::early_stop_checkpoints, Integers(0, 1000000),
        "training stops after this many checkpoints in a row without a greedy reward above the "
        "kept policy's (needs eval_interval > 0); the kept policy answers, as without it. 0: "
        "train for all train_episodes"},
       {"seed", &AgentCommonSpec::seed, Integers(0, 9007199254740991LL),
        "weights, exploration and replay sampling"}},
      CheckAgentCommonSpec};
  return table;
}

}  // namespace rlpos
