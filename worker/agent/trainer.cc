#include "agent/trainer.h"

namespace rlpos {

EpisodeRecord RunEpisode(Env& env, Agent& agent, std::uint64_t seed, bool learn,
                         const StepCallback& on_step) {
  const BoxSpace space = env.ObservationSpace();
  EpisodeRecord record;
  record.evaluation = !learn;
  std::vector<float> obs = space.Normalise(env.Reset(seed));
  ActionMask mask = env.ValidActions();
  double reward = 0.0;
  double loss_sum = 0.0;
  for (;;) {
    const int action = agent.Act(obs, mask, learn);
    StepResult step = env.Step(action);
    std::vector<float> next = space.Normalise(step.observation);
    ActionMask next_mask = env.ValidActions();
    if (learn) {
      const double loss = agent.Observe(
          {obs, action, static_cast<float>(step.reward), next, step.terminated, next_mask});
      if (loss >= 0) {
        ++record.updates;
        loss_sum += loss;
      }
    }
    record.total_reward += step.reward;
    reward = step.reward;
    ++record.steps;
    if (on_step)
      on_step(record.steps, action, step);
    obs = std::move(next);
    mask = std::move(next_mask);
    if (step.terminated || step.truncated)
      break;
  }
  record.epsilon = learn ? agent.Epsilon() : 0.0;
  record.mean_loss = record.updates > 0 ? loss_sum / record.updates : 0.0;
  record.final_reward = reward;
  record.final_info = env.LastInfo();
  return record;
}

TrainResult Train(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                  const EpisodeCallback& on_episode, const StepCallback& on_eval_step) {
  TrainResult result;
  for (int e = 0; e < spec.train_episodes + spec.eval_episodes; ++e) {
    const bool learn = e < spec.train_episodes;
    EpisodeRecord record = RunEpisode(env, agent, seed + static_cast<std::uint64_t>(e), learn,
                                      learn ? StepCallback() : on_eval_step);
    record.episode = e + 1;
    if (on_episode)
      on_episode(record);
    result.final_info = record.final_info;
    result.final_reward = record.final_reward;
    result.curve.push_back(std::move(record));
  }
  return result;
}

}  // namespace rlpos
