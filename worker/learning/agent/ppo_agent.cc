#include "worker/learning/agent/ppo_agent.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>

#include "worker/env/gym/team_state.h"
#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/ppo_network.h"
#include "worker/learning/agent_base/advantage_estimate.h"
#include "worker/learning/agent_base/flat_adam.h"
#include "worker/learning/agent_base/ppo_actor_head.h"
#include "worker/learning/agent_base/ppo_objective.h"
#include "worker/learning/agent_base/running_moments.h"
#include "worker/learning/agent_base/state_stream.h"

namespace rlpos {

struct PpoAgent::Impl {
  AgentSpec spec;
  PpoSpec ppo;
  int observation_dim;
  int action_count;
  // agent.ppo.centralised_critic: the critic's input is the observation, then the transition's
  // team state of this many values; 0: the observation alone.
  int team_state_dim;
  std::optional<SlotBlock> ue_slots;  // where the UE slots lie, for agent.ue_encoder
  // libtorch initialises, saves and loads the networks; plain float computes with them
  // (dense_network.h says why): ppo_network.h.
  PpoNetwork actor_net;
  PpoNetwork critic_net;
  FlatAdam actor_adam;
  FlatAdam critic_adam;
  std::mt19937_64 rng;
  RunningMoments reward_moments;
  std::vector<float> kept_actor;  // KeepPolicy's copy of the parameters
  std::vector<float> kept_critic;

  // The rollout: what Act saw and chose, then what Observe was told.
  std::vector<Transition> rollout;
  std::vector<ActionMask> masks;  // the mask at each transition's observation
  std::vector<float> log_probs;
  std::vector<int> streams;  // the env each transition came from (batched collection)
  // What the last Act (one row) or ActBatch (a row per env) chose with, until Observe.
  std::vector<ActionMask> pending_masks;
  std::vector<float> pending_log_probs;
  // Transitions per update: rollout_steps from each of the num_envs envs that collect them.
  std::int64_t rollout_size;
  std::int64_t planned_updates = 0;  // rollouts in the training; 0: no annealing
  std::int64_t done_updates = 0;     // rollouts learned from so far
  double last_entropy = 0.0;         // the last update's mean minibatch entropy, for progress lines

  // The actor, drawn first from torch's generator seeded with the agent's seed (the critic
  // draws next): libtorch's weight initialisation, as before.
  static PpoNetwork SeededActor(const AgentSpec& s, int obs_dim, int actions,
                                const std::optional<SlotBlock>& ue_slots) {
    torch::manual_seed(s.seed);
    return PpoNetwork(obs_dim, s.hidden, actions, s.ue_encoder, ue_slots);
  }

  Impl(const AgentSpec& s, int obs_dim, int actions, std::int64_t training_steps,
       const std::optional<SlotBlock>& ue_slots)
      : spec(s),
        ppo(s.ppo),
        observation_dim(obs_dim),
        action_count(actions),
        team_state_dim(s.ppo.centralised_critic ? kTeamStateWidth : 0),
        ue_slots(ue_slots),
        actor_net(SeededActor(s, obs_dim, actions, ue_slots)),
        critic_net(obs_dim + team_state_dim, s.hidden, 1, s.ue_encoder, ue_slots),
        actor_adam(actor_net.Parameters().size(), s.ppo.learning_rate, 1e-5),
        critic_adam(critic_net.Parameters().size(), s.ppo.learning_rate, 1e-5),
        rng(s.seed),
        rollout_size(std::int64_t{s.ppo.rollout_steps} * s.ppo.num_envs) {
    if (ppo.anneal_learning_rate && training_steps > 0)
      planned_updates = std::max<std::int64_t>(1, training_steps / rollout_size);
  }

  // rows x observation_dim, row-major, of the rollout's observations (or next observations).
  std::vector<float> Observations(bool next) const {
    std::vector<float> rows;
    rows.reserve(rollout.size() * static_cast<std::size_t>(observation_dim));
    for (const Transition& t : rollout) {
      const std::vector<float>& row = next ? t.next_observation : t.observation;
      rows.insert(rows.end(), row.begin(), row.begin() + observation_dim);
    }
    return rows;
  }

  // The actor's logits for `rows` observations, with kForbiddenLogit where a row's mask forbids the
  // action (a mask that allows nothing counts as no mask, as MaskPenalty).
  void Logits(const float* observations, int rows, const ActionMask* const* row_masks,
              std::vector<float>& logits) {
    logits.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(action_count));
    actor_net.Forward(observations, rows, logits.data());
    for (int r = 0; r < rows; ++r)
      MaskLogits(*row_masks[r], action_count, logits.data() + r * action_count);
  }

  // rows x the critic's input, row-major: each observation (or next observation), then its
  // team state with a centralised critic. The rollout's observations, when the critic has no
  // team state.
  std::vector<float> CriticInputs(bool next) const {
    if (team_state_dim == 0)
      return Observations(next);
    std::vector<float> rows;
    rows.reserve(rollout.size() * static_cast<std::size_t>(observation_dim + team_state_dim));
    for (const Transition& t : rollout) {
      const std::vector<float>& row = next ? t.next_observation : t.observation;
      const std::vector<float>& team = next ? t.next_team_state : t.team_state;
      rows.insert(rows.end(), row.begin(), row.begin() + observation_dim);
      rows.insert(rows.end(), team.begin(), team.end());
    }
    return rows;
  }

  // The critic's value of each of `rows` inputs.
  std::vector<float> Values(const std::vector<float>& inputs, int rows) {
    std::vector<float> values(static_cast<std::size_t>(rows));
    critic_net.Forward(inputs.data(), rows, values.data());
    return values;
  }

  // The advantages and returns of the rollout (EstimateAdvantages), from the critic's inputs of
  // its observations and of its next observations.
  AdvantageEstimate AdvantagesAndReturns(const std::vector<float>& obs,
                                         const std::vector<float>& next) {
    const int n = static_cast<int>(rollout.size());
    std::vector<float> rewards(rollout.size());
    for (std::size_t i = 0; i < rollout.size(); ++i) {
      const float r = rollout[i].reward;
      rewards[i] = spec.normalise_rewards ? reward_moments.Standardise(r) : r;
    }
    return EstimateAdvantages(rollout, streams, rewards, Values(obs, n), Values(next, n), ppo.gamma,
                              ppo.gae_lambda);
  }

  // Linear decay to 0 over the planned rollouts, as CleanRL's anneal_lr: the first rollout
  // learns at the full rate, the last at 1 / planned_updates of it.
  void AnnealLearningRate() {
    if (planned_updates == 0)
      return;
    const double left = std::max(
        0.0, 1.0 - static_cast<double>(done_updates) / static_cast<double>(planned_updates));
    actor_adam.SetLearningRate(ppo.learning_rate * left);
    critic_adam.SetLearningRate(ppo.learning_rate * left);
  }

  // An action by the probabilities p of the actions: with explore a sample (inverse CDF with
  // the agent's own generator: reproducible across libraries), otherwise the most probable
  // allowed one.
  int Choose(const float* p, const ActionMask& mask, bool explore) {
    if (!mask.empty() && std::none_of(mask.begin(), mask.end(), [](std::uint8_t a) { return a; }))
      throw std::invalid_argument("the action mask allows no action");
    const int action = explore
                           ? SampleAllowed(p, mask, action_count,
                                           std::uniform_real_distribution<double>(0.0, 1.0)(rng))
                           : MostProbableAllowed(p, mask, action_count);
    pending_masks.push_back(mask);
    pending_log_probs.push_back(std::log(std::max(p[action], 1e-30f)));
    return action;
  }

  void Add(Transition transition, std::size_t row, int stream) {
    const auto team = static_cast<std::size_t>(team_state_dim);
    if (transition.team_state.size() != team || transition.next_team_state.size() != team) {
      throw std::invalid_argument(
          team == 0 ? "PPO: a team state for a critic that sees the observation alone"
                    : "PPO: a centralised critic needs each transition's team state (" +
                          std::to_string(team) + " values, and as many after the step)");
    }
    reward_moments.Add(transition.reward);
    rollout.push_back(std::move(transition));
    masks.push_back(std::move(pending_masks.at(row)));
    log_probs.push_back(pending_log_probs.at(row));
    streams.push_back(stream);
  }

  // Scales both networks' gradients to a joint norm of at most max_grad_norm, as
  // torch::nn::utils::clip_grad_norm_ does over their parameters.
  void ClipGradients() {
    double squares = 0.0;
    for (PpoNetwork* net : {&actor_net, &critic_net}) {
      for (float g : net->Gradients())
        squares += static_cast<double>(g) * g;
    }
    const double coefficient = ppo.max_grad_norm / (std::sqrt(squares) + 1e-6);
    if (coefficient >= 1.0)
      return;
    const auto scale = static_cast<float>(coefficient);
    for (PpoNetwork* net : {&actor_net, &critic_net}) {
      for (float& g : net->Gradients())
        g *= scale;
    }
  }

  // The rollout as the minibatches read it, a row per transition.
  struct RolloutRows {
    std::vector<float> obs;
    std::vector<float> team_in;  // the critic's inputs, with a team state only
    std::vector<float> advantages;
    std::vector<float> returns;
    std::vector<int> actions;
  };

  // One minibatch's rows, gathered.
  struct MinibatchRows {
    std::vector<float> obs;
    std::vector<float> critic;  // with a team state only
    std::vector<const ActionMask*> masks;
    std::vector<int> actions;
    std::vector<float> old_log_probs;
    std::vector<float> advantages;
    std::vector<float> returns;
    std::vector<float> logits;
    std::vector<float> values;
  };

  RolloutRows ReadRollout() {
    RolloutRows in;
    in.obs = Observations(false);
    // Without a team state the critic reads the observations themselves: no second copy.
    if (team_state_dim > 0)
      in.team_in = CriticInputs(false);
    AdvantageEstimate estimate =
        AdvantagesAndReturns(team_state_dim > 0 ? in.team_in : in.obs, CriticInputs(true));
    in.advantages = std::move(estimate.advantages);
    in.returns = std::move(estimate.returns);
    in.actions.resize(rollout.size());
    for (std::size_t r = 0; r < rollout.size(); ++r)
      in.actions[r] = rollout[r].action;
    return in;
  }

  MinibatchRows SizedMinibatch(long size) const {
    const auto rows = static_cast<std::size_t>(size);
    const auto dim = static_cast<std::size_t>(observation_dim);
    MinibatchRows b;
    b.obs.resize(rows * dim);
    b.critic.resize(team_state_dim > 0 ? rows * (dim + static_cast<std::size_t>(team_state_dim))
                                       : 0);
    b.masks.resize(rows);
    b.actions.resize(rows);
    b.old_log_probs.resize(rows);
    b.advantages.resize(rows);
    b.returns.resize(rows);
    b.values.resize(rows);
    return b;
  }

  // Gathers rollout rows order[start], order[start + 1], ... into the minibatch `b`.
  void Gather(const RolloutRows& in, const std::vector<long>& order, long start,
              MinibatchRows& b) const {
    const auto dim = static_cast<std::size_t>(observation_dim);
    const auto critic_dim = dim + static_cast<std::size_t>(team_state_dim);
    for (std::size_t row = 0; row < b.masks.size(); ++row) {
      const auto i = static_cast<std::size_t>(order[static_cast<std::size_t>(start) + row]);
      std::copy(in.obs.begin() + static_cast<long>(i * dim),
                in.obs.begin() + static_cast<long>((i + 1) * dim),
                b.obs.begin() + static_cast<long>(row * dim));
      if (team_state_dim > 0) {
        std::copy(in.team_in.begin() + static_cast<long>(i * critic_dim),
                  in.team_in.begin() + static_cast<long>((i + 1) * critic_dim),
                  b.critic.begin() + static_cast<long>(row * critic_dim));
      }
      b.masks[row] = &masks[i];
      b.actions[row] = in.actions[i];
      b.old_log_probs[row] = log_probs[i];
      b.advantages[row] = in.advantages[i];
      b.returns[row] = in.returns[i];
    }
  }

  // One gradient step of both networks on the minibatch.
  PpoObjective Update(MinibatchRows& b) {
    const int rows = static_cast<int>(b.masks.size());
    Logits(b.obs.data(), rows, b.masks.data(), b.logits);
    critic_net.Forward(team_state_dim > 0 ? b.critic.data() : b.obs.data(), rows, b.values.data());
    const PpoMinibatch minibatch{rows,
                                 action_count,
                                 b.logits.data(),
                                 b.values.data(),
                                 b.actions.data(),
                                 b.old_log_probs.data(),
                                 b.advantages.data(),
                                 b.returns.data()};
    const PpoCoefficients coefficients{ppo.clip, ppo.entropy_coefficient, ppo.value_coefficient};
    PpoObjective objective = PpoLossAndGradients(minibatch, coefficients);
    actor_net.Backward(objective.d_logits.data());
    critic_net.Backward(objective.d_values.data());
    ClipGradients();
    actor_adam.Step(actor_net.Parameters(), actor_net.Gradients());
    critic_adam.Step(critic_net.Parameters(), critic_net.Gradients());
    return objective;
  }

  // The mean loss of the minibatch updates.
  double Learn() {
    AnnealLearningRate();
    ++done_updates;
    const RolloutRows in = ReadRollout();
    const long n = static_cast<long>(rollout.size());
    std::vector<long> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0L);
    const long size = std::max(1L, n / ppo.minibatches);
    MinibatchRows batch = SizedMinibatch(size);
    double loss_sum = 0.0;
    double entropy_sum = 0.0;
    int updates = 0;
    for (int epoch = 0; epoch < ppo.epochs; ++epoch) {
      std::shuffle(order.begin(), order.end(), rng);
      for (long start = 0; start + size <= n; start += size) {
        Gather(in, order, start, batch);
        const PpoObjective objective = Update(batch);
        loss_sum += objective.loss;
        entropy_sum += objective.entropy;
        ++updates;
      }
    }
    last_entropy = entropy_sum / std::max(updates, 1);
    rollout.clear();
    masks.clear();
    log_probs.clear();
    streams.clear();
    return loss_sum / std::max(updates, 1);
  }

  // The policy's action probabilities of `rows` observations (row-major), masked.
  std::vector<float> Probabilities(const float* observations, int rows,
                                   const ActionMask* const* row_masks) {
    std::vector<float> logits;
    Logits(observations, rows, row_masks, logits);
    std::vector<float> p(logits.size());
    for (int r = 0; r < rows; ++r) {
      Softmax(logits.data() + static_cast<std::ptrdiff_t>(r) * action_count, action_count,
              p.data() + static_cast<std::ptrdiff_t>(r) * action_count);
    }
    return p;
  }
};

PpoAgent::PpoAgent(const AgentSpec& spec, int observation_dim, int action_count,
                   std::int64_t training_steps, const std::optional<SlotBlock>& ue_slots) {
  if (observation_dim <= 0 || action_count <= 0)
    throw std::invalid_argument("PPO needs a non-empty observation and action space");
  impl_ = std::make_unique<Impl>(spec, observation_dim, action_count, training_steps, ue_slots);
}

PpoAgent::~PpoAgent() = default;

std::string PpoAgent::Algorithm() const {
  return "ppo";
}

std::vector<float> PpoAgent::Probabilities(const std::vector<float>& observation,
                                           const ActionMask& mask) const {
  if (static_cast<int>(observation.size()) < impl_->observation_dim)
    throw std::invalid_argument("PpoAgent: an observation shorter than the network's input");
  const ActionMask* row_mask = &mask;
  return impl_->Probabilities(observation.data(), 1, &row_mask);
}

double PpoAgent::LearningRate() const {
  return impl_->actor_adam.LearningRate();
}

std::string PpoAgent::ProgressText() const {
  char text[80];
  if (impl_->done_updates == 0) {
    std::snprintf(text, sizeof text, "learning rate %.3g", LearningRate());
  } else {
    std::snprintf(text, sizeof text, "entropy %.3f, learning rate %.3g", impl_->last_entropy,
                  LearningRate());
  }
  return text;
}

int PpoAgent::Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) {
  Impl& m = *impl_;
  const std::vector<float> p = Probabilities(observation, mask);
  m.pending_masks.clear();
  m.pending_log_probs.clear();
  return m.Choose(p.data(), mask, explore);
}

std::vector<int> PpoAgent::ActBatch(const std::vector<std::vector<float>>& observations,
                                    const std::vector<ActionMask>& masks) {
  Impl& m = *impl_;
  const std::size_t rows = observations.size();
  if (!masks.empty() && masks.size() != rows)
    throw std::invalid_argument("ActBatch: one mask per observation, or none");
  static const ActionMask kNoMask;
  const auto mask_of = [&](std::size_t r) -> const ActionMask& {
    return masks.empty() ? kNoMask : masks[r];
  };
  std::vector<float> stacked;
  stacked.reserve(rows * static_cast<std::size_t>(m.observation_dim));
  std::vector<const ActionMask*> mask_rows;
  for (std::size_t r = 0; r < rows; ++r) {
    if (static_cast<int>(observations[r].size()) < m.observation_dim)
      throw std::invalid_argument("ActBatch: an observation shorter than the network's input");
    stacked.insert(stacked.end(), observations[r].begin(),
                   observations[r].begin() + m.observation_dim);
    mask_rows.push_back(&mask_of(r));
  }
  const std::vector<float> p =
      rows == 0 ? std::vector<float>{}
                : m.Probabilities(stacked.data(), static_cast<int>(rows), mask_rows.data());
  m.pending_masks.clear();
  m.pending_log_probs.clear();
  std::vector<int> actions(rows);
  for (std::size_t r = 0; r < rows; ++r)
    actions[r] =
        m.Choose(p.data() + r * static_cast<std::size_t>(m.action_count), mask_of(r), true);
  return actions;
}

std::optional<double> PpoAgent::Observe(Transition transition) {
  Impl& m = *impl_;
  m.Add(std::move(transition), 0, 0);
  if (static_cast<std::int64_t>(m.rollout.size()) < m.rollout_size)
    return std::nullopt;
  return m.Learn();
}

std::optional<double> PpoAgent::ObserveBatch(std::vector<Transition> transitions,
                                             const std::vector<int>& envs) {
  Impl& m = *impl_;
  if (transitions.size() != m.pending_masks.size() || envs.size() != transitions.size())
    throw std::invalid_argument(
        "ObserveBatch: one transition and env per row of the last ActBatch");
  for (std::size_t r = 0; r < transitions.size(); ++r)
    m.Add(std::move(transitions[r]), r, envs[r]);
  if (static_cast<std::int64_t>(m.rollout.size()) < m.rollout_size)
    return std::nullopt;
  return m.Learn();
}

std::vector<int> PpoAgent::ActEach(const std::vector<std::vector<float>>& observations,
                                   const std::vector<ActionMask>& masks, bool explore) {
  if (explore)
    return ActBatch(observations, masks);
  std::vector<int> actions;
  for (std::size_t i = 0; i < observations.size(); ++i)
    actions.push_back(Act(observations[i], masks.at(i), false));
  return actions;
}

std::optional<double> PpoAgent::ObserveEach(std::vector<Transition> transitions) {
  std::vector<int> streams(transitions.size());
  std::iota(streams.begin(), streams.end(), 0);
  return ObserveBatch(std::move(transitions), streams);
}

bool PpoAgent::NeedsTeamState() const {
  return impl_->team_state_dim > 0;
}

void PpoAgent::KeepPolicy() {
  impl_->kept_actor = impl_->actor_net.Parameters();
  impl_->kept_critic = impl_->critic_net.Parameters();
}

void PpoAgent::RestoreKeptPolicy() {
  if (impl_->kept_actor.empty())
    throw std::logic_error("no policy kept to restore");
  impl_->actor_net.Parameters() = impl_->kept_actor;
  impl_->critic_net.Parameters() = impl_->kept_critic;
}

void PpoAgent::Save(const std::string& directory) const {
  std::filesystem::create_directories(directory);
  impl_->actor_net.Save(directory + "/policy.pt");
  impl_->critic_net.Save(directory + "/value.pt");
}

void PpoAgent::Load(const std::string& directory) {
  impl_->actor_net.Load(directory + "/policy.pt");
  // Acting needs only the actor: a policy exported from a campaign's artifacts has no value.pt.
  const std::string value = directory + "/value.pt";
  if (std::filesystem::exists(value))
    impl_->critic_net.Load(value);
}

namespace {
constexpr char kStateMagic[] = "rlpos-ppo-state-1";
// An agent with agent.ue_encoder: the UE encoder's widths and slots follow the spaces.
constexpr char kSetStateMagic[] = "rlpos-ppo-ueset-1";
static_assert(sizeof kStateMagic == sizeof kSetStateMagic);

std::vector<std::int32_t> SlotsOf(const std::optional<SlotBlock>& slots) {
  if (!slots)
    return {};
  return {slots->offset, slots->count, slots->width};
}

}  // namespace

bool PpoAgent::AtRolloutStart() const {
  // What the last act chose with is consumed by its observe; the next act starts afresh.
  return impl_->rollout.empty();
}

void PpoAgent::SaveTrainingState(const std::string& file) const {
  if (!AtRolloutStart())
    throw std::logic_error("PPO's training state is saved between rollouts only");
  const Impl& m = *impl_;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  const bool sets = !m.spec.ue_encoder.empty();
  out.write(sets ? kSetStateMagic : kStateMagic, sizeof kStateMagic);
  state::Write<std::int32_t>(out, m.observation_dim);
  state::Write<std::int32_t>(out, m.action_count);
  if (sets) {
    state::WriteVector(
        out, std::vector<std::int32_t>(m.spec.ue_encoder.begin(), m.spec.ue_encoder.end()));
    state::WriteVector(out, SlotsOf(m.ue_slots));
  }
  state::WriteVector(out, m.actor_net.Parameters());
  state::WriteVector(out, m.critic_net.Parameters());
  m.actor_adam.SaveState(out);
  m.critic_adam.SaveState(out);
  std::ostringstream rng;
  rng << m.rng;
  const std::string text = rng.str();
  state::WriteVector(out, std::vector<char>(text.begin(), text.end()));
  m.reward_moments.SaveState(out);
  state::WriteVector(out, m.kept_actor);
  state::WriteVector(out, m.kept_critic);
  state::Write(out, m.done_updates);
  state::Write(out, m.planned_updates);
  if (!out.flush())
    throw std::runtime_error(file + ": cannot write");
}

void PpoAgent::LoadTrainingState(const std::string& file) {
  Impl& m = *impl_;
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw std::runtime_error(file + ": cannot open");
  try {
    char magic[sizeof kStateMagic] = {};
    in.read(magic, sizeof magic);
    const bool sets = !m.spec.ue_encoder.empty();
    const char* other = sets ? kStateMagic : kSetStateMagic;
    if (in && std::memcmp(magic, other, sizeof magic) == 0) {
      throw std::runtime_error(sets ? "the state of an agent without agent.ue_encoder"
                                    : "the state of an agent with agent.ue_encoder");
    }
    if (!in || std::memcmp(magic, sets ? kSetStateMagic : kStateMagic, sizeof magic) != 0)
      throw std::runtime_error("not a PPO training state of this version");
    if (state::Read<std::int32_t>(in) != m.observation_dim ||
        state::Read<std::int32_t>(in) != m.action_count)
      throw std::runtime_error("the state of an agent with other spaces");
    if (sets) {
      const std::vector<std::int32_t> widths(m.spec.ue_encoder.begin(), m.spec.ue_encoder.end());
      const std::vector<std::int32_t> slots = SlotsOf(m.ue_slots);
      std::vector<std::int32_t> saved;
      state::ReadVector(in, saved, widths.size(), "agent.ue_encoder");
      if (saved != widths)
        throw std::runtime_error("the state of an agent with another agent.ue_encoder");
      state::ReadVector(in, saved, slots.size(), "UE slots");
      if (saved != slots)
        throw std::runtime_error("the state of an agent with other UE slots");
    }
    state::ReadVector(in, m.actor_net.Parameters(), m.actor_net.Parameters().size(), "actor");
    state::ReadVector(in, m.critic_net.Parameters(), m.critic_net.Parameters().size(), "critic");
    m.actor_adam.LoadState(in);
    m.critic_adam.LoadState(in);
    std::vector<char> text;
    const auto size = state::Read<std::uint64_t>(in);
    if (size > 100000)
      throw std::runtime_error("damaged generator state");
    text.resize(size);
    in.read(text.data(), static_cast<std::streamsize>(size));
    std::istringstream rng(std::string(text.begin(), text.end()));
    rng >> m.rng;
    if (!in || !rng)
      throw std::runtime_error("damaged generator state");
    m.reward_moments.LoadState(in);
    // No policy kept yet: empty.
    state::ReadVector(in, m.kept_actor, m.actor_net.Parameters().size(), "kept actor", true);
    state::ReadVector(in, m.kept_critic, m.critic_net.Parameters().size(), "kept critic", true);
    m.done_updates = state::Read<std::int64_t>(in);
    m.planned_updates = state::Read<std::int64_t>(in);
    if (!in || in.peek() != std::char_traits<char>::eof())
      throw std::runtime_error("damaged or truncated");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
}

}  // namespace rlpos
