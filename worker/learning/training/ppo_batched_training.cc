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

// The batch the agent acts on: the running envs' observations (taken from the round) and, when
// the env masks, their masks.
struct Batch {
  std::vector<std::vector<float>> observations;
  std::vector<ActionMask> masks;
};

// One round: env i flies training episode first + i, for i < records.size(), until each has
// ended; the others are stepped too (a batched env steps every env) and ignored.
class BatchedRound {
 public:
  BatchedRound(BatchedEnv& envs, Rows& rows, PpoAgent& agent, const AgentSpec& spec,
               std::vector<EpisodeRecord>& records)
      : envs_(envs),
        rows_(rows),
        agent_(agent),
        spec_(spec),
        records_(records),
        count_(records.size()),
        chosen_(envs.NumEnvs(), 0) {}

  void Start(std::uint64_t seed, int first) {
    const std::size_t n = envs_.NumEnvs();
    std::vector<std::optional<std::uint64_t>> seeds(n);
    std::vector<ResetOptions> resets(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int episode = first + static_cast<int>(i < count_ ? i : 0);
      seeds[i] = seed + static_cast<std::uint64_t>(episode);
      resets[i] = TrainingEpisodeOptions(spec_, episode).reset;
    }
    envs_.Reset(seeds, resets, rows_.Buffers());
    teams_ = agent_.NeedsTeamState();
    observations_.resize(count_);
    masks_.resize(count_);
    team_states_.resize(count_);
    for (std::size_t i = 0; i < count_; ++i) {
      observations_[i] = rows_.Observation(i);
      masks_[i] = rows_.Mask(i);
      team_states_[i] = TeamStateNow(envs_, i, teams_);
    }
    running_.assign(count_, true);
  }

  // Steps until every episode has ended; an update is counted in the episode of the lowest env
  // that took part in it.
  void Fly(std::vector<double>& loss_sums) {
    for (;;) {
      const std::vector<int> active = Running();
      if (active.empty())
        return;
      Batch batch = TakeBatch(active);
      const std::vector<int> actions = agent_.ActBatch(batch.observations, batch.masks);
      Step(active, actions);
      std::vector<Transition> transitions = Record(active, actions, batch);
      if (const std::optional<double> loss = agent_.ObserveBatch(std::move(transitions), active)) {
        const auto i = static_cast<std::size_t>(active.front());
        ++records_[i].updates;
        loss_sums[i] += *loss;
      }
    }
  }

 private:
  std::vector<int> Running() const {
    std::vector<int> active;
    for (std::size_t i = 0; i < count_; ++i) {
      if (running_[i])
        active.push_back(static_cast<int>(i));
    }
    return active;
  }

  Batch TakeBatch(const std::vector<int>& active) {
    Batch batch;
    batch.observations.resize(active.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
      const auto i = static_cast<std::size_t>(active[k]);
      batch.observations[k] = std::move(observations_[i]);
      if (rows_.Masked())
        batch.masks.push_back(std::move(masks_[i]));
    }
    return batch;
  }

  // The active envs move as chosen; the others stand (action 0).
  void Step(const std::vector<int>& active, const std::vector<int>& actions) {
    std::fill(chosen_.begin(), chosen_.end(), 0);
    for (std::size_t k = 0; k < active.size(); ++k)
      chosen_[static_cast<std::size_t>(active[k])] = actions[k];
    envs_.Step(chosen_.data(), envs_.NumEnvs(), rows_.Buffers());
  }

  // The step's transitions, one per active env; updates the episodes' records and what each env
  // observes next.
  std::vector<Transition> Record(const std::vector<int>& active, const std::vector<int>& actions,
                                 Batch& batch) {
    const int limit = spec_.train_episode_steps;
    std::vector<Transition> transitions(active.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
      const auto i = static_cast<std::size_t>(active[k]);
      EpisodeRecord& record = records_[i];
      Transition& t = transitions[k];
      std::vector<float> next = rows_.Observation(i);
      ActionMask next_mask = rows_.Mask(i);
      // agent.train_episode_steps: a time limit, so the next state still bootstraps.
      const bool truncated = rows_.Truncated(i) || (limit > 0 && record.steps + 1 >= limit);
      t.observation = std::move(batch.observations[k]);
      t.action = actions[k];
      t.reward = static_cast<float>(rows_.Reward(i));
      t.next_observation = next;
      t.terminal = rows_.Terminated(i);
      t.next_mask = next_mask;
      t.episode_end = rows_.Terminated(i) || truncated;
      t.team_state = std::move(team_states_[i]);
      t.next_team_state = TeamStateNow(envs_, i, teams_);
      team_states_[i] = t.next_team_state;
      record.total_reward += rows_.Reward(i);
      record.final_reward = rows_.Reward(i);
      ++record.steps;
      if (t.episode_end) {
        running_[i] = false;
        record.final_info = envs_.LastInfo(i);
      }
      observations_[i] = std::move(next);
      masks_[i] = std::move(next_mask);
    }
    return transitions;
  }

  BatchedEnv& envs_;
  Rows& rows_;
  PpoAgent& agent_;
  const AgentSpec& spec_;
  std::vector<EpisodeRecord>& records_;
  std::size_t count_;
  bool teams_ = false;
  std::vector<std::vector<float>> observations_;  // what env i observes now, normalised
  std::vector<ActionMask> masks_;
  std::vector<std::vector<float>> team_states_;
  std::vector<bool> running_;
  std::vector<std::int64_t> chosen_;  // the actions of a batched step, one per env
};

void FlyRound(BatchedEnv& envs, Rows& rows, PpoAgent& agent, const AgentSpec& spec,
              std::uint64_t seed, int first, std::vector<EpisodeRecord>& records,
              std::vector<double>& loss_sums) {
  BatchedRound round(envs, rows, agent, spec, records);
  round.Start(seed, first);
  round.Fly(loss_sums);
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
