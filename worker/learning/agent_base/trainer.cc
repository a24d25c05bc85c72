#include "worker/learning/agent_base/trainer.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace rlpos {

std::vector<double> ScaleToBox(const std::vector<float>& unit, const BoxSpace& box) {
  std::vector<double> out(unit.size());
  for (std::size_t i = 0; i < unit.size() && i < box.Dim(); ++i) {
    const double u = std::clamp(static_cast<double>(unit[i]), -1.0, 1.0);
    out[i] = std::clamp(box.low[i] + 0.5 * (u + 1.0) * (box.high[i] - box.low[i]), box.low[i],
                        box.high[i]);
  }
  return out;
}

EpisodeOptions GreedyEpisodeOptions(const AgentSpec& spec) {
  EpisodeOptions options;
  options.joint = spec.joint_steps;
  return options;
}

EpisodeOptions TrainingEpisodeOptions(const AgentSpec& spec, int episode) {
  EpisodeOptions options = GreedyEpisodeOptions(spec);
  const int every = spec.baseline_start_every;
  options.reset.random_start = spec.exploring_starts && !(every > 0 && (episode + 1) % every == 0);
  options.max_steps = spec.train_episode_steps;
  return options;
}

std::vector<float> TeamStateFor(const Env& env, std::size_t agent) {
  const std::vector<double> state = env.TeamStateOf(agent);
  return std::vector<float>(state.begin(), state.end());  // its bounds are [0, 1] already
}

namespace {

std::vector<std::vector<float>> NormaliseEach(const BoxSpace& space,
                                              const std::vector<std::vector<double>>& rows) {
  std::vector<std::vector<float>> out;
  out.reserve(rows.size());
  for (const auto& row : rows)
    out.push_back(space.Normalise(row));
  return out;
}

std::vector<ActionMask> MasksOf(const Env& env) {
  std::vector<ActionMask> masks;
  for (std::size_t a = 0; a < env.AgentCount(); ++a)
    masks.push_back(env.ValidActionsOf(a));
  return masks;
}

// Every agent's team state, if the agent learns with them; otherwise none.
std::vector<std::vector<float>> TeamStatesFor(const Env& env, const Agent& agent, bool learn) {
  std::vector<std::vector<float>> states;
  if (learn && agent.NeedsTeamState()) {
    for (std::size_t a = 0; a < env.AgentCount(); ++a)
      states.push_back(TeamStateFor(env, a));
  }
  return states;
}

// What an episode's steps add up to, the same whether its agents act in turns or at once.
class EpisodeTally {
 public:
  explicit EpisodeTally(bool learn) { record_.evaluation = !learn; }
  int Steps() const { return record_.steps; }
  // One step's reward and the loss of the update it led to, if any.
  void Add(double reward, const std::optional<double>& loss) {
    if (loss) {
      ++record_.updates;
      loss_sum_ += *loss;
    }
    record_.total_reward += reward;
    record_.final_reward = reward;
    ++record_.steps;
  }
  EpisodeRecord Finish(const Env& env, const Agent& agent) {
    record_.epsilon = record_.evaluation ? 0.0 : agent.Epsilon();
    record_.mean_loss = record_.updates > 0 ? loss_sum_ / record_.updates : 0.0;
    record_.final_info = env.LastInfo();
    return std::move(record_);
  }

 private:
  EpisodeRecord record_;
  double loss_sum_ = 0.0;
};

// RunEpisode with every agent acting at once (options.joint, several agents).
EpisodeRecord RunJointEpisode(Env& env, Agent& agent, std::uint64_t seed, bool learn,
                              const StepCallback& on_step, const EpisodeOptions& options) {
  const BoxSpace space = env.ObservationSpace();
  const BoxSpace box = env.ContinuousActionSpace();
  EpisodeTally tally(learn);
  env.Reset(seed, options.reset);
  std::vector<std::vector<float>> obs = NormaliseEach(space, env.AgentObservations());
  std::vector<ActionMask> masks = MasksOf(env);
  std::vector<std::vector<float>> teams = TeamStatesFor(env, agent, learn);
  for (;;) {
    std::vector<Transition> transitions(obs.size());
    JointStepResult step;
    if (agent.Continuous()) {
      std::vector<std::vector<double>> displacements;
      for (std::size_t a = 0; a < obs.size(); ++a) {
        transitions[a].continuous_action = agent.ActContinuous(obs[a], learn);
        displacements.push_back(ScaleToBox(transitions[a].continuous_action, box));
      }
      step = env.JointStepContinuous(displacements);
    } else {
      const std::vector<int> actions = agent.ActEach(obs, masks, learn);
      for (std::size_t a = 0; a < obs.size(); ++a)
        transitions[a].action = actions[a];
      step = env.JointStep(actions);
    }
    std::vector<std::vector<float>> next = NormaliseEach(space, step.observations);
    std::vector<ActionMask> next_masks = MasksOf(env);
    std::vector<std::vector<float>> next_teams = TeamStatesFor(env, agent, learn);
    if (options.max_steps > 0 && tally.Steps() + 1 >= options.max_steps)
      step.truncated = true;  // a time limit: the next state still bootstraps
    const int first_action = transitions.front().action;
    std::optional<double> loss;
    if (learn) {
      for (std::size_t a = 0; a < transitions.size(); ++a) {
        Transition& t = transitions[a];
        t.observation = std::move(obs[a]);
        t.reward = static_cast<float>(step.reward);
        t.next_observation = next[a];
        t.terminal = step.terminated;
        t.next_mask = next_masks[a];
        t.episode_end = step.terminated || step.truncated;
        if (!teams.empty()) {
          t.team_state = std::move(teams[a]);
          t.next_team_state = next_teams[a];
        }
      }
      loss = agent.ObserveEach(std::move(transitions));
    }
    tally.Add(step.reward, loss);
    if (on_step) {
      StepResult single;
      single.observation = step.observations.front();
      single.reward = step.reward;
      single.terminated = step.terminated;
      single.truncated = step.truncated;
      single.info = step.info;
      on_step(tally.Steps(), first_action, single);
    }
    obs = std::move(next);
    masks = std::move(next_masks);
    teams = std::move(next_teams);
    if (step.terminated || step.truncated)
      break;
  }
  return tally.Finish(env, agent);
}

}  // namespace

EpisodeRecord RunEpisode(Env& env, Agent& agent, std::uint64_t seed, bool learn,
                         const StepCallback& on_step, const EpisodeOptions& options) {
  if (options.joint && env.AgentCount() > 1)
    return RunJointEpisode(env, agent, seed, learn, on_step, options);
  const BoxSpace space = env.ObservationSpace();
  EpisodeTally tally(learn);
  std::vector<float> obs = space.Normalise(env.Reset(seed, options.reset));
  ActionMask mask = env.ValidActions();
  const BoxSpace box = env.ContinuousActionSpace();
  const bool teams = learn && agent.NeedsTeamState();
  // The team state of the agent the observation is of: the one whose turn it is.
  const auto team_now = [&env] {
    return TeamStateFor(env, static_cast<std::size_t>(env.LastInfo().active_uav));
  };
  std::vector<float> team = teams ? team_now() : std::vector<float>{};
  for (;;) {
    Transition t;
    StepResult step;
    if (agent.Continuous()) {
      t.continuous_action = agent.ActContinuous(obs, learn);
      step = env.StepContinuous(ScaleToBox(t.continuous_action, box));
    } else {
      t.action = agent.Act(obs, mask, learn);
      step = env.Step(t.action);
    }
    const int action = t.action;
    std::vector<float> next = space.Normalise(step.observation);
    ActionMask next_mask = env.ValidActions();
    if (options.max_steps > 0 && tally.Steps() + 1 >= options.max_steps)
      step.truncated = true;  // a time limit: the next state still bootstraps
    std::optional<double> loss;
    if (learn) {
      t.observation = obs;
      t.reward = static_cast<float>(step.reward);
      t.next_observation = next;
      t.terminal = step.terminated;
      t.next_mask = next_mask;
      t.episode_end = step.terminated || step.truncated;
      if (teams) {
        t.team_state = std::move(team);
        t.next_team_state = team_now();
        team = t.next_team_state;
      }
      loss = agent.Observe(std::move(t));
    }
    tally.Add(step.reward, loss);
    if (on_step)
      on_step(tally.Steps(), action, step);
    obs = std::move(next);
    mask = std::move(next_mask);
    if (step.terminated || step.truncated)
      break;
  }
  return tally.Finish(env, agent);
}

std::uint64_t EvaluationSeed(const AgentSpec& spec, std::uint64_t seed, int k) {
  return seed + static_cast<std::uint64_t>(spec.train_episodes) + static_cast<std::uint64_t>(k);
}

bool Checkpoints::Due(const AgentSpec& spec, int before, int done) {
  if (spec.eval_interval <= 0)
    return false;
  return done / spec.eval_interval > before / spec.eval_interval || done == spec.train_episodes;
}

EpisodeRecord Checkpoints::Score(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                                 int episode, TrainResult& result) {
  // The evaluation's first seed: checkpoints are scored on the episode the answer comes from.
  EpisodeRecord check = RunEpisode(env, agent, EvaluationSeed(spec, seed, 0), false, nullptr,
                                   GreedyEpisodeOptions(spec));
  check.episode = episode;
  check.checkpoint = true;
  stale_ = kept_ && check.final_reward <= *kept_ ? stale_ + 1 : 0;
  if (!kept_ || check.final_reward >= *kept_) {
    agent.KeepPolicy();
    kept_ = check.final_reward;
    result.policy_episode = episode;
  }
  return check;
}

bool Checkpoints::StopEarly(const AgentSpec& spec) const {
  return spec.early_stop_checkpoints > 0 && stale_ >= spec.early_stop_checkpoints;
}

void Checkpoints::Evaluate(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                           TrainResult& result, const EpisodeCallback& on_episode,
                           const StepCallback& on_eval_step) const {
  if (kept_) {
    agent.RestoreKeptPolicy();
  } else {
    result.policy_episode = spec.train_episodes;
  }
  for (int k = 0; k < spec.eval_episodes; ++k) {
    EpisodeRecord record = RunEpisode(env, agent, EvaluationSeed(spec, seed, k), false,
                                      on_eval_step, GreedyEpisodeOptions(spec));
    record.episode = spec.train_episodes + k + 1;
    result.final_info = record.final_info;
    result.final_reward = record.final_reward;
    if (on_episode)
      on_episode(record);
    result.curve.push_back(std::move(record));
  }
}

double LearntReward(const AgentSpec& spec, double reward, double& best) {
  const double rise = std::max(0.0, reward - best);
  best = std::max(best, reward);
  return spec.improvement_reward ? rise : reward;
}

void CheckPerScenarioTraining(const AgentSpec& spec) {
  if (spec.improvement_reward) {
    throw std::invalid_argument(
        "agent.improvement_reward: learnt only in training across scenarios (rlpos-sim train "
        "--generated or --scenarios)");
  }
}

TrainResult Train(Env& env, Agent& agent, const AgentSpec& spec, std::uint64_t seed,
                  const EpisodeCallback& on_episode, const StepCallback& on_eval_step) {
  CheckPerScenarioTraining(spec);
  TrainResult result;
  const auto add = [&](EpisodeRecord record) {
    if (on_episode)
      on_episode(record);
    result.curve.push_back(std::move(record));
  };
  Checkpoints checkpoints;
  for (int e = 0; e < spec.train_episodes; ++e) {
    EpisodeRecord record = RunEpisode(env, agent, seed + static_cast<std::uint64_t>(e), true,
                                      nullptr, TrainingEpisodeOptions(spec, e));
    record.episode = e + 1;
    add(std::move(record));
    result.episodes_trained = e + 1;
    if (!Checkpoints::Due(spec, e, e + 1))
      continue;
    add(checkpoints.Score(env, agent, spec, seed, e + 1, result));
    if (checkpoints.StopEarly(spec))
      break;
  }
  checkpoints.Evaluate(env, agent, spec, seed, result, on_episode, on_eval_step);
  return result;
}

}  // namespace rlpos
