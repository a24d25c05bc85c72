#pragma once
// PPO's hyperparameters (clipped objective, GAE): declared once here, as AgentSpec::ppo; read by
// the agent (worker/learning/agent/ppo_agent.cc) and batched training (worker/learning/training).
// Defaults: CleanRL's ppo.py (Atari/classic control) except the learning rate, gamma, rollout and
// epochs: that set is tuned for millions of steps, and these were chosen when our training was the
// paper's 10 episodes of 1,000 steps (docs/agents.md, "PPO and SAC"). PPO's training budget is
// agent.train_episodes's, whose default per algorithm is in agent_hyperparameters.h.
#include "common/config/config_error.h"
#include "common/config/setting.h"

namespace rlpos {

struct PpoSpec {
  double learning_rate = 1e-3;
  double gamma = 0.9;
  double gae_lambda = 0.95;
  double clip = 0.2;
  double entropy_coefficient = 0.01;
  double value_coefficient = 0.5;
  double max_grad_norm = 0.5;
  int rollout_steps = 256;
  int epochs = 10;
  int minibatches = 4;
  bool anneal_learning_rate = true;
  int num_envs = 1;
  bool centralised_critic = false;
};

inline void CheckPpoSpec(const PpoSpec& p, const ObjectReader& reader) {
  if (p.minibatches > p.rollout_steps)
    throw ConfigError(reader.PathOf("minibatches"), "must not exceed rollout_steps");
}

inline const SettingsTable<PpoSpec>& PpoHyperparameters() {
  static const SettingsTable<PpoSpec> table{
      "ppo",
      "/agent/ppo",
      "PPO on the discrete moves; CleanRL's ppo.py values where they differ.",
      {{"learning_rate", &PpoSpec::learning_rate, PositiveAtMost(1.0),
        "Adam (eps 1e-5), actor and critic together. CleanRL: 2.5e-4"},
       {"gamma", &PpoSpec::gamma, Between(0.0, 1.0), "discount. CleanRL: 0.99"},
       {"gae_lambda", &PpoSpec::gae_lambda, Between(0.0, 1.0), "GAE's lambda"},
       {"clip", &PpoSpec::clip, PositiveAtMost(1.0), "the surrogate objective's ratio clip"},
       {"entropy_coefficient", &PpoSpec::entropy_coefficient, NonNegative(),
        "weight of the entropy bonus"},
       {"value_coefficient", &PpoSpec::value_coefficient, NonNegative(),
        "weight of the value loss"},
       {"max_grad_norm", &PpoSpec::max_grad_norm, Positive(), "gradient norm clipping"},
       {"rollout_steps", &PpoSpec::rollout_steps, Integers(2, 1000000),
        "transitions per env per update (CleanRL's num_steps: an update learns from num_envs x "
        "rollout_steps). CleanRL: 128"},
       {"epochs", &PpoSpec::epochs, Integers(1, 1000), "passes over a rollout. CleanRL: 4"},
       {"minibatches", &PpoSpec::minibatches, Integers(1, 1000000),
        "minibatches per pass (each of num_envs x rollout_steps / minibatches transitions); at "
        "most rollout_steps"},
       {"anneal_learning_rate", &PpoSpec::anneal_learning_rate, NoRange(),
        "the rate falls linearly to 0 over the training's rollouts (train_episodes x steps per "
        "episode / rollout_steps), the first at the full rate (CleanRL's anneal_lr, on there): "
        "late updates then refine the policy instead of knocking it off its best"},
       {"num_envs", &PpoSpec::num_envs, Integers(1, 4096),
        "analytic envs that collect the rollouts together, with one batched forward pass of the "
        "policy for them all per step; each update learns from num_envs x rollout_steps "
        "transitions, so num_envs times fewer updates (and gradient steps) per training, of "
        "num_envs times more transitions each (CleanRL's num_envs). Env i of n flies training "
        "episodes i, i + n, ... in rounds of n. 1: one env, the seed stream of a single env. "
        "Packet fidelity (one network per process): one env collects the num_envs x "
        "rollout_steps transitions"},
       {"centralised_critic", &PpoSpec::centralised_critic, NoRange(),
        "the critic sees, beside the acting UAV's own observation, the team's state (the shares "
        "of UEs in LoS and with their demand met, the throughput, and each UAV's share of the "
        "UEs, in slots of fixed count: the same layout in every scenario), as MAPPO's "
        "centralised critic does with agent.joint_steps (every UAV acting at once on its own "
        "observation, one shared policy). The actor still acts on the observation alone, so "
        "placing needs nothing more; the wider critic is a training matter"}},
      CheckPpoSpec};
  return table;
}

}  // namespace rlpos
