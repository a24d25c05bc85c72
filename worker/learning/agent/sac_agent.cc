#include "worker/learning/agent/sac_agent.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>

#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/mlp.h"
#include "worker/learning/agent_base/running_moments.h"

namespace rlpos {
namespace {

constexpr double kLogStdMin = -5.0;
constexpr double kLogStdMax = 2.0;

struct PolicySample {
  torch::Tensor action;    // in [-1, 1]
  torch::Tensor log_prob;  // of the squashed action, one per row
};

}  // namespace

struct SacAgent::Impl {
  AgentSpec spec;
  SacSpec sac;
  int observation_dim;
  int action_dim;
  torch::nn::Sequential actor{nullptr};  // -> mean and log std per action dimension
  torch::nn::Sequential q1{nullptr}, q2{nullptr}, q1_target{nullptr}, q2_target{nullptr};
  torch::Tensor log_alpha;
  double target_entropy;
  std::unique_ptr<torch::optim::Adam> actor_optimizer, q_optimizer, alpha_optimizer;
  ReplayBuffer replay;
  std::mt19937_64 rng;
  std::int64_t steps = 0;
  RunningMoments reward_moments;
  KeptNetworks kept;

  Impl(const AgentSpec& s, int obs_dim, int act_dim)
      : spec(s),
        sac(s.sac),
        observation_dim(obs_dim),
        action_dim(act_dim),
        target_entropy(-static_cast<double>(act_dim)),
        replay(static_cast<std::size_t>(s.sac.replay_capacity)),
        rng(s.seed) {
    torch::manual_seed(s.seed);  // weight initialisation and the policy's noise
    actor = MakeMlp(s.hidden, obs_dim, 2 * act_dim);
    q1 = MakeMlp(s.hidden, obs_dim + act_dim, 1);
    q2 = MakeMlp(s.hidden, obs_dim + act_dim, 1);
    q1_target = MakeMlp(s.hidden, obs_dim + act_dim, 1);
    q2_target = MakeMlp(s.hidden, obs_dim + act_dim, 1);
    CopyParameters(q1, q1_target);
    CopyParameters(q2, q2_target);
    log_alpha = torch::zeros({1}, torch::requires_grad());
    actor_optimizer = std::make_unique<torch::optim::Adam>(
        actor->parameters(), torch::optim::AdamOptions(sac.policy_learning_rate));
    std::vector<torch::Tensor> q_parameters = q1->parameters();
    for (const auto& p : q2->parameters())
      q_parameters.push_back(p);
    q_optimizer = std::make_unique<torch::optim::Adam>(
        q_parameters, torch::optim::AdamOptions(sac.q_learning_rate));
    alpha_optimizer = std::make_unique<torch::optim::Adam>(
        std::vector<torch::Tensor>{log_alpha}, torch::optim::AdamOptions(sac.q_learning_rate));
  }

  double Alpha() const { return sac.alpha ? *sac.alpha : log_alpha.exp().item<double>(); }

  std::pair<torch::Tensor, torch::Tensor> MeanAndLogStd(const torch::Tensor& obs) {
    const auto parts = actor->forward(obs).chunk(2, 1);
    // tanh keeps the log std in [min, max] with a gradient everywhere.
    const torch::Tensor log_std =
        kLogStdMin + 0.5 * (kLogStdMax - kLogStdMin) * (torch::tanh(parts[1]) + 1.0);
    return {parts[0], log_std};
  }

  PolicySample Sample(const torch::Tensor& obs) {
    const auto [mean, log_std] = MeanAndLogStd(obs);
    const torch::Tensor std = log_std.exp();
    const torch::Tensor noise = torch::randn_like(mean);
    const torch::Tensor x = mean + std * noise;
    const torch::Tensor y = torch::tanh(x);
    // Gaussian log density, minus the log of tanh's Jacobian.
    const torch::Tensor gaussian = -0.5 * noise.pow(2) - log_std - 0.5 * std::log(2.0 * M_PI);
    const torch::Tensor log_prob = (gaussian - torch::log(1.0 - y.pow(2) + 1e-6)).sum(1);
    return {y, log_prob};
  }

  torch::Tensor Q(torch::nn::Sequential& net, const torch::Tensor& obs,
                  const torch::Tensor& action) {
    return net->forward(torch::cat({obs, action}, 1)).squeeze(1);
  }

  // The `field` of the replayed transitions at `indices`, one row each.
  torch::Tensor Stack(const std::vector<std::size_t>& indices, int dim,
                      const std::vector<float> Transition::*field) const {
    return StackRows(
        indices.size(),
        dim, [&](std::size_t r) -> const auto& { return replay.At(indices[r]).*field; });
  }

  double Learn() {
    const auto indices = replay.SampleIndices(static_cast<std::size_t>(sac.batch_size), rng);
    const long n = static_cast<long>(indices.size());
    const torch::Tensor obs = Stack(indices, observation_dim, &Transition::observation);
    const torch::Tensor next = Stack(indices, observation_dim, &Transition::next_observation);
    const torch::Tensor actions = Stack(indices, action_dim, &Transition::continuous_action);
    torch::Tensor rewards = torch::empty({n});
    torch::Tensor not_terminal = torch::empty({n});
    auto reward_at = rewards.accessor<float, 1>();  // not tensor[r] = x: a tensor op each
    auto not_terminal_at = not_terminal.accessor<float, 1>();
    for (long r = 0; r < n; ++r) {
      const Transition& tr = replay.At(indices[static_cast<std::size_t>(r)]);
      reward_at[r] = spec.normalise_rewards ? reward_moments.Standardise(tr.reward) : tr.reward;
      not_terminal_at[r] = tr.terminal ? 0.0f : 1.0f;
    }
    const double alpha = Alpha();
    torch::Tensor target;
    {
      torch::NoGradGuard no_grad;
      const PolicySample next_pi = Sample(next);
      const torch::Tensor next_q =
          torch::min(Q(q1_target, next, next_pi.action), Q(q2_target, next, next_pi.action));
      target = rewards + static_cast<float>(sac.gamma) * not_terminal *
                             (next_q - static_cast<float>(alpha) * next_pi.log_prob);
    }
    const torch::Tensor q_loss =
        torch::mse_loss(Q(q1, obs, actions), target) + torch::mse_loss(Q(q2, obs, actions), target);
    q_optimizer->zero_grad();
    q_loss.backward();
    q_optimizer->step();

    const PolicySample pi = Sample(obs);
    const torch::Tensor q_pi = torch::min(Q(q1, obs, pi.action), Q(q2, obs, pi.action));
    const torch::Tensor actor_loss = (static_cast<float>(alpha) * pi.log_prob - q_pi).mean();
    actor_optimizer->zero_grad();
    actor_loss.backward();
    actor_optimizer->step();

    if (!sac.alpha) {
      const torch::Tensor alpha_loss =
          -(log_alpha.exp() * (pi.log_prob.detach() + target_entropy)).mean();
      alpha_optimizer->zero_grad();
      alpha_loss.backward();
      alpha_optimizer->step();
    }
    SoftUpdate(q1, q1_target, sac.tau);
    SoftUpdate(q2, q2_target, sac.tau);
    return q_loss.item<double>();
  }
};

SacAgent::SacAgent(const AgentSpec& spec, int observation_dim, int action_dim) {
  if (observation_dim <= 0 || action_dim <= 0)
    throw std::invalid_argument("SAC needs a non-empty observation and action space");
  impl_ = std::make_unique<Impl>(spec, observation_dim, action_dim);
}

SacAgent::~SacAgent() = default;

std::string SacAgent::Algorithm() const {
  return "sac";
}

double SacAgent::Alpha() const {
  return impl_->Alpha();
}

std::string SacAgent::ProgressText() const {
  char text[32];
  std::snprintf(text, sizeof text, "alpha %.4f", Alpha());
  return text;
}

int SacAgent::Act(const std::vector<float>&, const ActionMask&, bool) {
  throw std::logic_error("sac acts on a continuous action space");
}

std::vector<float> SacAgent::ActContinuous(const std::vector<float>& observation, bool explore) {
  Impl& m = *impl_;
  std::vector<float> action(static_cast<std::size_t>(m.action_dim));
  if (explore && m.steps < m.sac.warmup_steps) {
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    for (float& a : action)
      a = uniform(m.rng);
    return action;
  }
  torch::NoGradGuard no_grad;
  const torch::Tensor obs = Row(observation);
  const torch::Tensor y =
      (explore ? m.Sample(obs).action : torch::tanh(m.MeanAndLogStd(obs).first)).contiguous();
  std::copy(y.data_ptr<float>(), y.data_ptr<float>() + y.numel(), action.begin());
  return action;
}

std::optional<double> SacAgent::Observe(Transition transition) {
  Impl& m = *impl_;
  if (static_cast<int>(transition.continuous_action.size()) != m.action_dim)
    throw std::invalid_argument("a SAC transition needs its continuous action");
  m.reward_moments.Add(transition.reward);
  m.replay.Add(std::move(transition));
  ++m.steps;
  if (m.steps < m.sac.warmup_steps || m.steps % m.sac.update_interval != 0)
    return std::nullopt;
  return m.Learn();
}

void SacAgent::KeepPolicy() {
  impl_->kept.Keep({impl_->actor});
}

void SacAgent::RestoreKeptPolicy() {
  impl_->kept.Restore({impl_->actor});
}

void SacAgent::Save(const std::string& directory) const {
  std::filesystem::create_directories(directory);
  torch::save(impl_->actor, directory + "/policy.pt");
}

void SacAgent::Load(const std::string& directory) {
  LoadNetwork(directory + "/policy.pt", impl_->actor, impl_->spec.hidden, impl_->observation_dim,
              2 * impl_->action_dim);
}

}  // namespace rlpos
