#include "worker/learning/training/ppo_batched_training.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "worker/env/gym/team_state.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/env/vector_env/batched_env.h"

namespace rlpos {
namespace {

// What a step or reset of the batched env writes, one row per env, and the rows as the agent
// takes them (normalised observations, masks).
class Rows {
 public:
  explicit Rows(const BatchedEnv& envs)
      : space_(envs.ObservationSpace()),
        n_(envs.NumEnvs()),
        dim_(envs.ObservationDim()),
        actions_(envs.ActionCount()),
        masked_(envs.HasActionMask()),
        observations_(n_ * dim_),
        rewards_(n_),
        terminated_(new bool[n_]()),
        truncated_(new bool[n_]()),
        masks_(masked_ ? n_ * actions_ : 0) {
    buffers_.raw_observations = observations_.data();
    buffers_.rewards = rewards_.data();
    buffers_.terminated = terminated_.get();
    buffers_.truncated = truncated_.get();
    buffers_.action_mask = masked_ ? masks_.data() : nullptr;
  }

  const BatchBuffers& Buffers() const { return buffers_; }
  bool Masked() const { return masked_; }
  std::vector<float> Observation(std::size_t i) const {
    const auto row = observations_.begin() + static_cast<long>(i * dim_);
    return space_.Normalise(std::vector<double>(row, row + static_cast<long>(dim_)));
  }
  // Empty where the env masks nothing, as UavPositioningEnv::ValidActions.
  ActionMask Mask(std::size_t i) const {
    if (!masked_)
      return {};
    const auto row = masks_.begin() + static_cast<long>(i * actions_);
    return ActionMask(row, row + static_cast<long>(actions_));
  }
  double Reward(std::size_t i) const { return rewards_[i]; }
  bool Terminated(std::size_t i) const { return terminated_[i]; }
  bool Truncated(std::size_t i) const { return truncated_[i]; }

 private:
  BoxSpace space_;
  std::size_t n_, dim_, actions_;
  bool masked_;
  std::vector<double> observations_;
  std::vector<double> rewards_;
  std::unique_ptr<bool[]> terminated_, truncated_;  // bool*, which std::vector<bool> has not
  std::vector<std::int8_t> masks_;
  BatchBuffers buffers_;
};

// Env i's team state now, of the UAV whose turn it is (its observation's), for a centralised
// critic; empty when the agent needs none.
std::vector<float> TeamStateNow(const BatchedEnv& envs, std::size_t i, bool needed) {
  if (!needed)
    return {};
  const StepInfo& info = envs.LastInfo(i);
  const std::vector<double> state =
      TeamState(envs.ScenarioOf(i), info, static_cast<std::size_t>(info.active_uav));
  return std::vector<float>(state.begin(), state.end());
}

// One round: env i flies training episode first + i, for i < records.size(), until each has
// ended; the others are stepped too (a batched env steps every env) and ignored.
void FlyRound(BatchedEnv& envs, Rows& rows, PpoAgent& agent, const AgentSpec& spec,
              std::uint64_t seed, int first, std::vector<EpisodeRecord>& records,
              std::vector<double>& loss_sums) {
  const std::size_t n = envs.NumEnvs();
  const std::size_t count = records.size();
  std::vector<std::optional<std::uint64_t>> seeds(n);
  std::vector<ResetOptions> resets(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int episode = first + static_cast<int>(i < count ? i : 0);
    seeds[i] = seed + static_cast<std::uint64_t>(episode);
    resets[i] = TrainingEpisodeOptions(spec, episode).reset;
  }
  envs.Reset(seeds, resets, rows.Buffers());
  const bool teams = agent.NeedsTeamState();
  std::vector<std::vector<float>> observations(count);
  std::vector<ActionMask> masks(count);
  std::vector<std::vector<float>> team_states(count);
  for (std::size_t i = 0; i < count; ++i) {
    observations[i] = rows.Observation(i);
    masks[i] = rows.Mask(i);
    team_states[i] = TeamStateNow(envs, i, teams);
  }
  std::vector<bool> running(count, true);
  std::vector<int> active;
  std::vector<std::int64_t> chosen(n, 0);
  const int limit = spec.train_episode_steps;
  for (;;) {
    active.clear();
    for (std::size_t i = 0; i < count; ++i) {
      if (running[i])
        active.push_back(static_cast<int>(i));
    }
    if (active.empty())
      return;
    std::vector<std::vector<float>> batch(active.size());
    std::vector<ActionMask> batch_masks;
    for (std::size_t k = 0; k < active.size(); ++k) {
      const auto i = static_cast<std::size_t>(active[k]);
      batch[k] = std::move(observations[i]);
      if (rows.Masked())
        batch_masks.push_back(std::move(masks[i]));
    }
    const std::vector<int> actions = agent.ActBatch(batch, batch_masks);
    std::fill(chosen.begin(), chosen.end(), 0);
    for (std::size_t k = 0; k < active.size(); ++k)
      chosen[static_cast<std::size_t>(active[k])] = actions[k];
    envs.Step(chosen.data(), n, rows.Buffers());

    std::vector<Transition> transitions(active.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
      const auto i = static_cast<std::size_t>(active[k]);
      EpisodeRecord& record = records[i];
      Transition& t = transitions[k];
      std::vector<float> next = rows.Observation(i);
      ActionMask next_mask = rows.Mask(i);
      // agent.train_episode_steps: a time limit, so the next state still bootstraps.
      const bool truncated = rows.Truncated(i) || (limit > 0 && record.steps + 1 >= limit);
      t.observation = std::move(batch[k]);
      t.action = actions[k];
      t.reward = static_cast<float>(rows.Reward(i));
      t.next_observation = next;
      t.terminal = rows.Terminated(i);
      t.next_mask = next_mask;
      t.episode_end = rows.Terminated(i) || truncated;
      t.team_state = std::move(team_states[i]);
      t.next_team_state = TeamStateNow(envs, i, teams);
      team_states[i] = t.next_team_state;
      record.total_reward += rows.Reward(i);
      record.final_reward = rows.Reward(i);
      ++record.steps;
      if (t.episode_end) {
        running[i] = false;
        record.final_info = envs.LastInfo(i);
      }
      observations[i] = std::move(next);
      masks[i] = std::move(next_mask);
    }
    // An update is counted in the episode of the lowest env that took part in it.
    if (const std::optional<double> loss = agent.ObserveBatch(std::move(transitions), active)) {
      const auto i = static_cast<std::size_t>(active.front());
      ++records[i].updates;
      loss_sums[i] += *loss;
    }
  }
}

}  // namespace

TrainResult TrainPpoBatched(const Scenario& scenario, PpoAgent& agent, std::uint64_t seed,
                            std::size_t threads, const EpisodeCallback& on_episode,
                            const StepCallback& on_eval_step) {
  const AgentSpec& spec = scenario.agent;
  CheckPerScenarioTraining(spec);
  if (spec.joint_steps && scenario.uavs.size() > 1) {
    throw std::invalid_argument(
        "agent.joint_steps: several UAVs moving at once train on one env (agent.ppo.num_envs 1) "
        "for now");
  }
  BatchedEnvOptions options;
  options.num_envs = static_cast<std::size_t>(spec.ppo.num_envs);
  options.threads = threads;
  BatchedEnv envs({scenario}, options);
  Rows rows(envs);
  UavPositioningEnv single(scenario);  // the checkpoints' and the evaluation's
  TrainResult result;
  Checkpoints checkpoints;
  const auto add = [&](EpisodeRecord record) {
    if (on_episode)
      on_episode(record);
    result.curve.push_back(std::move(record));
  };
  const int n = spec.ppo.num_envs;
  for (int first = 0; first < spec.train_episodes; first += n) {
    const int count = std::min(n, spec.train_episodes - first);
    std::vector<EpisodeRecord> records(static_cast<std::size_t>(count));
    std::vector<double> loss_sums(records.size(), 0.0);
    FlyRound(envs, rows, agent, spec, seed, first, records, loss_sums);
    for (std::size_t i = 0; i < records.size(); ++i) {
      EpisodeRecord& record = records[i];
      record.episode = first + static_cast<int>(i) + 1;
      record.epsilon = agent.Epsilon();
      record.mean_loss = record.updates > 0 ? loss_sums[i] / record.updates : 0.0;
      add(std::move(record));
    }
    const int done = first + count;
    result.episodes_trained = done;
    if (!Checkpoints::Due(spec, first, done))
      continue;
    add(checkpoints.Score(single, agent, spec, seed, done, result));
    if (checkpoints.StopEarly(spec))
      break;
  }
  checkpoints.Evaluate(single, agent, spec, seed, result, on_episode, on_eval_step);
  return result;
}

}  // namespace rlpos
