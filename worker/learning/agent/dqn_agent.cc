#include "worker/learning/agent/dqn_agent.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/mlp.h"
#include "worker/learning/agent_base/running_moments.h"

namespace rlpos {

struct DqnAgent::Impl {
  AgentSpec spec;
  DqnSpec dqn;
  int observation_dim;
  int action_count;
  torch::nn::Sequential online{nullptr};
  torch::nn::Sequential target{nullptr};
  std::unique_ptr<torch::optim::Adam> optimizer;
  ReplayBuffer replay;
  EpsilonSchedule epsilon;
  std::mt19937_64 rng;
  std::int64_t steps = 0;
  RunningMoments reward_moments;
  KeptNetworks kept;

  Impl(const AgentSpec& s, int obs_dim, int actions)
      : spec(s),
        dqn(s.dqn),
        observation_dim(obs_dim),
        action_count(actions),
        replay(static_cast<std::size_t>(s.dqn.replay_capacity)),
        epsilon{s.dqn.epsilon_start, s.dqn.epsilon_end, s.dqn.epsilon_decay_steps},
        rng(s.seed) {
    torch::manual_seed(s.seed);  // weight initialisation
    online = MakeMlp(s.hidden, obs_dim, actions);
    target = MakeMlp(s.hidden, obs_dim, actions);
    CopyParameters(online, target);
    optimizer = std::make_unique<torch::optim::Adam>(
        online->parameters(), torch::optim::AdamOptions(s.dqn.learning_rate));
  }

  torch::Tensor Batch(const std::vector<std::size_t>& indices, bool next) const {
    return StackRows(
        indices.size(), observation_dim, [&](std::size_t r) -> const auto& {
          const Transition& tr = replay.At(indices[r]);
          return next ? tr.next_observation : tr.observation;
        });
  }

  double Learn() {
    const auto indices = replay.SampleIndices(static_cast<std::size_t>(dqn.batch_size), rng);
    const long n = static_cast<long>(indices.size());
    torch::Tensor obs = Batch(indices, false);
    torch::Tensor next = Batch(indices, true);
    torch::Tensor actions = torch::empty({n}, torch::kLong);
    torch::Tensor rewards = torch::empty({n});
    torch::Tensor not_terminal = torch::empty({n});
    std::vector<const ActionMask*> next_masks;
    bool masked = false;
    // Accessors, not tensor[r] = x: each of those is a tensor op, three per row and update.
    auto action_at = actions.accessor<std::int64_t, 1>();
    auto reward_at = rewards.accessor<float, 1>();
    auto not_terminal_at = not_terminal.accessor<float, 1>();
    for (long r = 0; r < n; ++r) {
      const auto& tr = replay.At(indices[r]);
      action_at[r] = tr.action;
      reward_at[r] = spec.normalise_rewards ? reward_moments.Standardise(tr.reward) : tr.reward;
      not_terminal_at[r] = tr.terminal ? 0.0f : 1.0f;
      next_masks.push_back(&tr.next_mask);
      masked = masked || !tr.next_mask.empty();
    }
    torch::Tensor target_q;
    {
      torch::NoGradGuard no_grad;
      torch::Tensor next_q = target->forward(next);
      const torch::Tensor penalty =
          masked ? MaskPenalty(next_masks, action_count, -INFINITY) : torch::Tensor();
      const auto allowed_only = [&](const torch::Tensor& q) { return masked ? q + penalty : q; };
      torch::Tensor best;
      if (dqn.double_dqn) {
        // The online network picks the action, the target network values it.
        const torch::Tensor pick = allowed_only(online->forward(next)).argmax(1, true);
        best = next_q.gather(1, pick).squeeze(1);
      } else {
        best = std::get<0>(allowed_only(next_q).max(1));
      }
      target_q = rewards + static_cast<float>(dqn.gamma) * not_terminal * best;
    }
    torch::Tensor q = online->forward(obs).gather(1, actions.unsqueeze(1)).squeeze(1);
    torch::Tensor loss = torch::mse_loss(q, target_q);
    optimizer->zero_grad();
    loss.backward();
    optimizer->step();
    return loss.item<double>();
  }
};

DqnAgent::DqnAgent(const AgentSpec& spec, int observation_dim, int action_count)
    : impl_(std::make_unique<Impl>(spec, observation_dim, action_count)) {
  if (observation_dim <= 0 || action_count <= 0) {
    throw std::invalid_argument("DQN needs a non-empty observation and action space");
  }
}

DqnAgent::~DqnAgent() = default;

std::vector<float> DqnAgent::QValues(const std::vector<float>& observation) const {
  torch::NoGradGuard no_grad;
  torch::Tensor q = impl_->online->forward(Row(observation)).squeeze(0).contiguous();
  return std::vector<float>(q.data_ptr<float>(), q.data_ptr<float>() + q.numel());
}

int DqnAgent::Act(const std::vector<float>& observation, const ActionMask& mask, bool explore) {
  std::vector<int> allowed;
  for (int a = 0; a < impl_->action_count; ++a) {
    if (Allowed(mask, a))
      allowed.push_back(a);
  }
  if (allowed.empty())
    throw std::invalid_argument("the action mask allows no action");
  if (explore) {
    std::uniform_real_distribution<double> coin(0.0, 1.0);
    if (coin(impl_->rng) < Epsilon()) {
      std::uniform_int_distribution<std::size_t> pick(0, allowed.size() - 1);
      return allowed[pick(impl_->rng)];
    }
  }
  const auto q = QValues(observation);
  int best = allowed.front();
  for (int a : allowed) {
    if (q[a] > q[best])
      best = a;
  }
  return best;
}

std::optional<double> DqnAgent::Observe(Transition transition) {
  Impl& m = *impl_;
  m.reward_moments.Add(transition.reward);
  m.replay.Add(std::move(transition));
  ++m.steps;
  std::optional<double> loss;
  if (m.steps >= m.dqn.warmup_steps &&
      m.replay.Size() >= static_cast<std::size_t>(std::max<std::int64_t>(m.dqn.batch_size, 1))) {
    loss = m.Learn();
  }
  if (m.steps % m.dqn.target_update_interval == 0)
    CopyParameters(m.online, m.target);
  return loss;
}

std::string DqnAgent::Algorithm() const {
  return "dqn";
}

std::string DqnAgent::ProgressText() const {
  char text[32];
  std::snprintf(text, sizeof text, "epsilon %.2f", Epsilon());
  return text;
}

double DqnAgent::Epsilon() const {
  return impl_->epsilon.At(impl_->steps);
}

void DqnAgent::KeepPolicy() {
  impl_->kept.Keep({impl_->online});
}

void DqnAgent::RestoreKeptPolicy() {
  impl_->kept.Restore({impl_->online});
  CopyParameters(impl_->online, impl_->target);
}

void DqnAgent::Save(const std::string& directory) const {
  std::filesystem::create_directories(directory);
  torch::save(impl_->online, directory + "/policy.pt");
}

void DqnAgent::Load(const std::string& directory) {
  LoadNetwork(directory + "/policy.pt", impl_->online, impl_->spec.hidden, impl_->observation_dim,
              impl_->action_count);
  CopyParameters(impl_->online, impl_->target);
}

}  // namespace rlpos
