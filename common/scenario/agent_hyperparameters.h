#pragma once
// The hyperparameters every algorithm shares (training length, checkpoints, seed, reward
// standardisation): declared once here, read by worker/learning/agent and
// worker/programs/rl_commands/train_command.cc. Their keys sit in the scenario's "agent" object.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/config/config_error.h"
#include "common/config/setting.h"

namespace rlpos {

// Four of them have a default per algorithm, which AgentCommonDefaults gives and the parser
// starts from; the initialisers below are only the default algorithm's (dqn). They were chosen on
// a generated training set and reported on a held-out one (docs/agents.md, "Defaults chosen on
// scenarios nobody tuned for").
struct AgentCommonSpec {
  bool normalise_rewards = true;
  int train_episodes = 1000;
  int train_episode_steps = 25;
  bool exploring_starts = true;
  int baseline_start_every = 0;
  bool joint_steps = false;
  bool improvement_reward = false;
  int eval_episodes = 1;
  int eval_interval = 50;
  int early_stop_checkpoints = 0;
  std::uint64_t seed = 1;
};

// The shared keys' defaults for `algorithm` with `uavs` UAVs. PPO, on-policy, needs more samples
// than DQN; SAC (its steps cost most) learns more from shorter episodes from more starts. Both
// need a share of them from the baseline: from random starts alone their greedy policies missed
// the way from there where the best cells are close to it. Several UAVs take turns, so each moves
// in only 1/uavs of the steps: the training grows to (uavs + 1) / 2 times one UAV's (three UAVs:
// twice), what the time budget allows (docs/agents.md). The docs table shows the one-UAV defaults.
inline AgentCommonSpec AgentCommonDefaults(const std::string& algorithm, std::size_t uavs) {
  AgentCommonSpec spec;
  if (algorithm == "dqn") {
    spec.train_episodes = 1000;
    spec.train_episode_steps = 25;
    spec.baseline_start_every = 0;
    spec.eval_interval = 50;
  } else if (algorithm == "ppo") {
    spec.train_episodes = 4000;
    spec.train_episode_steps = 25;
    spec.baseline_start_every = 4;
    spec.eval_interval = 100;
  } else if (algorithm == "sac") {
    spec.train_episodes = 2500;
    spec.train_episode_steps = 10;
    spec.baseline_start_every = 4;
    spec.eval_interval = 100;
  }
  const auto n = static_cast<int>(std::max<std::size_t>(uavs, 1));
  spec.train_episodes = spec.train_episodes * (n + 1) / 2;
  return spec;
}

inline void CheckAgentCommonSpec(const AgentCommonSpec& a, const ObjectReader& reader) {
  if (a.early_stop_checkpoints > 0 && a.eval_interval == 0)
    throw ConfigError(reader.PathOf("early_stop_checkpoints"),
                      "needs checkpoints: set agent.eval_interval > 0");
}

inline const SettingsTable<AgentCommonSpec>& AgentCommonHyperparameters() {
  static const SettingsTable<AgentCommonSpec> table{
      "agent",
      "/agent",
      "Every algorithm's: training length, checkpoints, seed. Where the default differs by "
      "algorithm, the column gives each one's.",
      {{"normalise_rewards", &AgentCommonSpec::normalise_rewards, NoRange(),
        "TD targets (and PPO's and SAC's) use rewards standardised by the running mean and "
        "standard deviation of the rewards seen so far. Not in the paper. The greedy policy of "
        "an env that never terminates (ours) is unchanged by it, but the network no longer has "
        "to resolve 1 % differences (scenario A) on top of a large constant"},
       {"train_episodes", &AgentCommonSpec::train_episodes, Integers(1, 1000000),
        "training episodes. The default is one UAV's; with n UAVs, (n + 1) / 2 times as many"},
       {"train_episode_steps", &AgentCommonSpec::train_episode_steps, Integers(0, 1000000),
        "a training episode ends (truncated, as Gymnasium's max_episode_steps) after this many "
        "steps; checkpoints and the evaluation fly the env's whole episode. 0: the env's "
        "episode (env.episode_duration / env.decision_interval steps). With exploring starts, "
        "many short episodes from many starts teach more than a few long ones: 25 steps (125 m "
        "at 5 m a move) cross the zone"},
       {"exploring_starts", &AgentCommonSpec::exploring_starts, NoRange(),
        "each training episode starts every UAV at a point of its zone drawn from the episode's "
        "seed, on the lattice of env.step moves through its baseline; checkpoints and the "
        "evaluation start from the baseline. The policy then learns the whole zone, not only "
        "the cells on its way from the baseline, and finds a better region it would not fly "
        "through (Sutton and Barto's exploring starts)"},
       {"baseline_start_every", &AgentCommonSpec::baseline_start_every, Integers(0, 1000000),
        "with exploring starts, every this many-th training episode starts from the baseline "
        "instead, as the checkpoints and the evaluation do, so that the policy also learns the "
        "way from there. 0: none. PPO's and SAC's default has some: from random starts alone, "
        "their greedy policies missed cells a few moves above the baseline"},
       {"joint_steps", &AgentCommonSpec::joint_steps, NoRange(),
        "several UAVs: every step moves every UAV at once (as rlpos.parallel_env), each by the "
        "shared policy from its own observation (parameter sharing, as MAPPO's actors), all "
        "rewarded with the team's reward; training, checkpoints, the evaluation and a replay of "
        "the policy fly that way. false: the UAVs take turns, one move each. One UAV: no "
        "difference"},
       {"improvement_reward", &AgentCommonSpec::improvement_reward, NoRange(),
        "training across scenarios (train --generated or --scenarios; per-scenario training "
        "refuses it): each transition is learnt with the reward's rise above the best of its "
        "episode so far, its start state's included (0 when there is none), instead of the "
        "reward. An episode's return is then its best reward minus its start's, what a "
        "placement that keeps the best step of its flight gains, and a dip on the way to a "
        "better place costs nothing (the improvement reward of learnt local search, Wu et al. "
        "2021). Pair it with the \"best\" observation, which tells how far below that best "
        "the state is. Validation and every reported reward are the env's"},
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
