#include "worker/agent/ppo_agent.h"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <stdexcept>

#include "worker/agent/libtorch.h"
#include "worker/agent/mlp.h"
#include "worker/agent/running_moments.h"

namespace rlpos {
namespace {

// The logit of the actions a mask forbids: their probability is 0, and unlike -inf it keeps
// 0 * log(0) in the entropy finite.
constexpr float kForbidden = -1e9f;

}  // namespace

struct PpoAgent::Impl {
  AgentSpec spec;
  PpoSpec ppo;
  int observation_dim;
  int action_count;
  torch::nn::Sequential actor{nullptr};
  torch::nn::Sequential critic{nullptr};
  std::unique_ptr<torch::optim::Adam> optimizer;
  std::mt19937_64 rng;
  RunningMoments reward_moments;
  KeptNetworks kept;

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

  Impl(const AgentSpec& s, int obs_dim, int actions, std::int64_t training_steps)
      : spec(s),
        ppo(s.ppo),
        observation_dim(obs_dim),
        action_count(actions),
        rng(s.seed),
        rollout_size(std::int64_t{s.ppo.rollout_steps} * s.ppo.num_envs) {
    if (ppo.anneal_learning_rate && training_steps > 0)
      planned_updates = std::max<std::int64_t>(1, training_steps / rollout_size);
    torch::manual_seed(s.seed);  // weight initialisation
    actor = MakeMlp(s.hidden, obs_dim, actions);
    critic = MakeMlp(s.hidden, obs_dim, 1);
    std::vector<torch::Tensor> parameters = actor->parameters();
    for (const auto& p : critic->parameters())
      parameters.push_back(p);
    optimizer = std::make_unique<torch::optim::Adam>(
        parameters, torch::optim::AdamOptions(ppo.learning_rate).eps(1e-5));
  }

  torch::Tensor Observations(bool next) const {
    return StackRows(
        rollout.size(), observation_dim, [&](std::size_t r) -> const auto& {
          return next ? rollout[r].next_observation : rollout[r].observation;
        });
  }

  // Advantages by GAE(lambda). A truncated episode bootstraps from the value of its last next
  // observation; a terminal one from 0; no advantage is carried across an episode's end, nor
  // from one env's transitions to another's (the last of each env's is cut as the rollout's).
  std::pair<torch::Tensor, torch::Tensor> AdvantagesAndReturns(const torch::Tensor& obs,
                                                               const torch::Tensor& next) {
    torch::NoGradGuard no_grad;
    const torch::Tensor values = critic->forward(obs).squeeze(1).contiguous();
    const torch::Tensor next_values = critic->forward(next).squeeze(1).contiguous();
    const long n = static_cast<long>(rollout.size());
    torch::Tensor advantages = torch::empty({n});
    auto adv = advantages.accessor<float, 1>();
    auto v = values.accessor<float, 1>();
    auto nv = next_values.accessor<float, 1>();
    const int stream_count = 1 + *std::max_element(streams.begin(), streams.end());
    std::vector<float> carried_of(static_cast<std::size_t>(stream_count), 0.0f);
    std::vector<bool> seen(static_cast<std::size_t>(stream_count), false);
    for (long t = n - 1; t >= 0; --t) {
      const Transition& tr = rollout[static_cast<std::size_t>(t)];
      const auto stream = static_cast<std::size_t>(streams[static_cast<std::size_t>(t)]);
      float& carried = carried_of[stream];
      const float reward =
          spec.normalise_rewards ? reward_moments.Standardise(tr.reward) : tr.reward;
      const float bootstrap = tr.terminal ? 0.0f : static_cast<float>(ppo.gamma) * nv[t];
      const float delta = reward + bootstrap - v[t];
      if (tr.episode_end || !seen[stream])
        carried = 0.0f;
      seen[stream] = true;
      carried = delta + static_cast<float>(ppo.gamma * ppo.gae_lambda) * carried;
      adv[t] = carried;
    }
    return {advantages, advantages + values};
  }

  // Linear decay to 0 over the planned rollouts, as CleanRL's anneal_lr: the first rollout
  // learns at the full rate, the last at 1 / planned_updates of it.
  void AnnealLearningRate() {
    if (planned_updates == 0)
      return;
    const double left = std::max(
        0.0, 1.0 - static_cast<double>(done_updates) / static_cast<double>(planned_updates));
    for (auto& group : optimizer->param_groups())
      static_cast<torch::optim::AdamOptions&>(group.options()).lr(ppo.learning_rate * left);
  }

  // An action by the probabilities p of the actions: with explore a sample (inverse CDF with
  // the agent's own generator: reproducible across libraries), otherwise the most probable
  // allowed one.
  int Choose(const float* p, const ActionMask& mask, bool explore) {
    if (!mask.empty() && std::none_of(mask.begin(), mask.end(), [](std::uint8_t a) { return a; }))
      throw std::invalid_argument("the action mask allows no action");
    int action = -1;
    if (explore) {
      const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
      double cumulative = 0.0;
      for (int a = 0; a < action_count; ++a) {
        if (!Allowed(mask, a) || p[a] <= 0.0f)
          continue;
        action = a;  // the last allowed action takes what rounding leaves over
        cumulative += p[a];
        if (u < cumulative)
          break;
      }
    } else {
      for (int a = 0; a < action_count; ++a) {
        if (Allowed(mask, a) && (action < 0 || p[a] > p[action]))
          action = a;
      }
    }
    pending_masks.push_back(mask);
    pending_log_probs.push_back(std::log(std::max(p[action], 1e-30f)));
    return action;
  }

  void Add(Transition transition, std::size_t row, int stream) {
    reward_moments.Add(transition.reward);
    rollout.push_back(std::move(transition));
    masks.push_back(std::move(pending_masks.at(row)));
    log_probs.push_back(pending_log_probs.at(row));
    streams.push_back(stream);
  }

  // The mean loss of the minibatch updates.
  double Learn() {
    AnnealLearningRate();
    ++done_updates;
    const torch::Tensor obs = Observations(false);
    const auto [advantages, returns] = AdvantagesAndReturns(obs, Observations(true));
    const long n = static_cast<long>(rollout.size());
    torch::Tensor actions = torch::empty({n}, torch::kLong);
    auto action_at = actions.accessor<std::int64_t, 1>();  // not tensor[r] = x: a tensor op each
    for (long r = 0; r < n; ++r)
      action_at[r] = rollout[static_cast<std::size_t>(r)].action;
    const torch::Tensor old_log_probs = torch::tensor(log_probs);

    std::vector<long> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0L);
    const long size = std::max(1L, n / ppo.minibatches);
    double loss_sum = 0.0;
    int updates = 0;
    for (int epoch = 0; epoch < ppo.epochs; ++epoch) {
      std::shuffle(order.begin(), order.end(), rng);
      for (long start = 0; start + size <= n; start += size) {
        const std::vector<long> chosen(order.begin() + start, order.begin() + start + size);
        const torch::Tensor index = torch::tensor(chosen, torch::kLong);
        std::vector<const ActionMask*> batch_masks;
        for (long i : chosen)
          batch_masks.push_back(&masks[static_cast<std::size_t>(i)]);
        const torch::Tensor logits = actor->forward(obs.index_select(0, index)) +
                                     MaskPenalty(batch_masks, action_count, kForbidden);
        const torch::Tensor log_p = torch::log_softmax(logits, 1);
        const torch::Tensor taken =
            log_p.gather(1, actions.index_select(0, index).unsqueeze(1)).squeeze(1);
        const torch::Tensor entropy = -(log_p.exp() * log_p).sum(1).mean();
        torch::Tensor adv = advantages.index_select(0, index);
        adv = (adv - adv.mean()) / (adv.std() + 1e-8);
        const torch::Tensor ratio = (taken - old_log_probs.index_select(0, index)).exp();
        const torch::Tensor policy_loss =
            torch::max(-adv * ratio, -adv * ratio.clamp(1.0 - ppo.clip, 1.0 + ppo.clip)).mean();
        const torch::Tensor value = critic->forward(obs.index_select(0, index)).squeeze(1);
        const torch::Tensor value_loss =
            0.5 * (value - returns.index_select(0, index)).pow(2).mean();
        const torch::Tensor loss =
            policy_loss - ppo.entropy_coefficient * entropy + ppo.value_coefficient * value_loss;
        optimizer->zero_grad();
        loss.backward();
        torch::nn::utils::clip_grad_norm_(optimizer->param_groups()[0].params(), ppo.max_grad_norm);
        optimizer->step();
        loss_sum += loss.item<double>();
        ++updates;
      }
    }
    rollout.clear();
    masks.clear();
    log_probs.clear();
    streams.clear();
    return loss_sum / std::max(updates, 1);
  }
};

PpoAgent::PpoAgent(const AgentSpec& spec, int observation_dim, int action_count,
                   std::int64_t training_steps) {
  if (observation_dim <= 0 || action_count <= 0)
    throw std::invalid_argument("PPO needs a non-empty observation and action space");
  impl_ = std::make_unique<Impl>(spec, observation_dim, action_count, training_steps);
}

PpoAgent::~PpoAgent() = default;

std::string PpoAgent::Algorithm() const {
  return "ppo";
}

std::vector<float> PpoAgent::Probabilities(const std::vector<float>& observation,
                                           const ActionMask& mask) const {
  torch::NoGradGuard no_grad;
  const torch::Tensor logits = impl_->actor->forward(Row(observation)) +
                               MaskPenalty({&mask}, impl_->action_count, kForbidden);
  const torch::Tensor p = torch::softmax(logits, 1).squeeze(0).contiguous();
  return std::vector<float>(p.data_ptr<float>(), p.data_ptr<float>() + p.numel());
}

double PpoAgent::LearningRate() const {
  return static_cast<torch::optim::AdamOptions&>(impl_->optimizer->param_groups()[0].options())
      .lr();
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
  torch::Tensor p;
  {
    torch::NoGradGuard no_grad;
    std::vector<const ActionMask*> mask_rows;
    for (std::size_t r = 0; r < rows; ++r)
      mask_rows.push_back(&mask_of(r));
    const torch::Tensor logits =
        m.actor->forward(StackRows(
            rows,
            m.observation_dim, [&](std::size_t r) -> const auto& { return observations[r]; })) +
        MaskPenalty(mask_rows, m.action_count, kForbidden);
    p = torch::softmax(logits, 1).contiguous();
  }
  m.pending_masks.clear();
  m.pending_log_probs.clear();
  std::vector<int> actions(rows);
  const float* row = p.data_ptr<float>();
  for (std::size_t r = 0; r < rows; ++r, row += m.action_count)
    actions[r] = m.Choose(row, mask_of(r), true);
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

void PpoAgent::KeepPolicy() {
  impl_->kept.Keep({impl_->actor, impl_->critic});
}

void PpoAgent::RestoreKeptPolicy() {
  impl_->kept.Restore({impl_->actor, impl_->critic});
}

void PpoAgent::Save(const std::string& directory) const {
  std::filesystem::create_directories(directory);
  torch::save(impl_->actor, directory + "/policy.pt");
  torch::save(impl_->critic, directory + "/value.pt");
}

void PpoAgent::Load(const std::string& directory) {
  LoadNetwork(directory + "/policy.pt", impl_->actor, impl_->spec.hidden, impl_->observation_dim,
              impl_->action_count);
  // Acting needs only the actor: a policy exported from a campaign's artifacts has no value.pt.
  const std::string value = directory + "/value.pt";
  if (std::filesystem::exists(value))
    LoadNetwork(value, impl_->critic, impl_->spec.hidden, impl_->observation_dim, 1);
}

}  // namespace rlpos
