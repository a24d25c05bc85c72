// PPO's loss and gradients by hand against libtorch's autograd of the same loss, written as the
// agent wrote it with tensors: clipped and unclipped rows, masked actions, the entropy bonus and
// the value loss.
#include "worker/learning/agent_base/ppo_objective.h"

#include <gtest/gtest.h>

#include <vector>

#include "worker/learning/agent/libtorch.h"

namespace rlpos {
namespace {

constexpr int kRows = 12;
constexpr int kActions = 5;
constexpr float kForbidden = -1e9f;

std::vector<float> TensorFloats(const torch::Tensor& t) {
  const torch::Tensor c = t.detach().contiguous();
  return std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
}

TEST(PpoObjective, LossAndGradientsAreAutogradsWithinRounding) {
  torch::manual_seed(7);
  torch::Tensor penalty = torch::zeros({kRows, kActions});
  penalty.index_put_({0, 3}, kForbidden);  // a masked action in two rows
  penalty.index_put_({5, 0}, kForbidden);
  const torch::Tensor raw_logits = torch::randn({kRows, kActions}).requires_grad_(true);
  const torch::Tensor values = torch::randn({kRows}).requires_grad_(true);
  const torch::Tensor actions = torch::tensor({0, 1, 2, 4, 1, 2, 3, 4, 0, 1, 2, 3}, torch::kLong);
  // Old log-probabilities far from today's in some rows, so that both sides of the clip occur.
  const torch::Tensor old_log_probs = torch::randn({kRows}) * 0.5 - 1.6;
  const torch::Tensor advantages = torch::randn({kRows});
  const torch::Tensor returns = torch::randn({kRows});
  const PpoCoefficients c{0.2, 0.01, 0.5};

  const torch::Tensor logits = raw_logits + penalty;
  const torch::Tensor log_p = torch::log_softmax(logits, 1);
  const torch::Tensor taken = log_p.gather(1, actions.unsqueeze(1)).squeeze(1);
  const torch::Tensor entropy = -(log_p.exp() * log_p).sum(1).mean();
  const torch::Tensor adv = (advantages - advantages.mean()) / (advantages.std() + 1e-8);
  const torch::Tensor ratio = (taken - old_log_probs).exp();
  const torch::Tensor policy_loss =
      torch::max(-adv * ratio, -adv * ratio.clamp(1.0 - c.clip, 1.0 + c.clip)).mean();
  const torch::Tensor value_loss = 0.5 * (values - returns).pow(2).mean();
  const torch::Tensor loss = policy_loss - c.entropy * entropy + c.value * value_loss;
  loss.backward();
  const std::vector<float> ratios = TensorFloats(ratio);
  const int clipped = static_cast<int>(std::count_if(
      ratios.begin(), ratios.end(), [&](float r) { return r < 1.0 - c.clip || r > 1.0 + c.clip; }));
  ASSERT_GT(clipped, 0);
  ASSERT_LT(clipped, kRows);

  const std::vector<float> z = TensorFloats(logits);
  const std::vector<float> v = TensorFloats(values);
  std::vector<int> a;
  for (std::int64_t x : std::vector<std::int64_t>(actions.data_ptr<std::int64_t>(),
                                                  actions.data_ptr<std::int64_t>() + kRows))
    a.push_back(static_cast<int>(x));
  const std::vector<float> old = TensorFloats(old_log_probs);
  const std::vector<float> ad = TensorFloats(advantages);
  const std::vector<float> ret = TensorFloats(returns);
  const PpoObjective got = PpoLossAndGradients(
      {kRows, kActions, z.data(), v.data(), a.data(), old.data(), ad.data(), ret.data()}, c);

  EXPECT_NEAR(got.loss, loss.item<double>(), 1e-5);
  const std::vector<float> d_logits = TensorFloats(raw_logits.grad());
  ASSERT_EQ(got.d_logits.size(), d_logits.size());
  for (std::size_t i = 0; i < d_logits.size(); ++i)
    EXPECT_NEAR(got.d_logits[i], d_logits[i], 1e-6f) << "logit " << i;
  EXPECT_EQ(got.d_logits[3], 0.0f);  // row 0's masked action
  const std::vector<float> d_values = TensorFloats(values.grad());
  for (std::size_t i = 0; i < d_values.size(); ++i)
    EXPECT_NEAR(got.d_values[i], d_values[i], 1e-6f) << "value " << i;
}

TEST(PpoObjective, RefusesAnActionOutsideTheSpace) {
  const std::vector<float> z(3, 0.0f), one(1, 0.0f);
  const int action = 3;
  EXPECT_THROW(PpoLossAndGradients(
                   {1, 3, z.data(), one.data(), &action, one.data(), one.data(), one.data()}, {}),
               std::invalid_argument);
}

TEST(PpoObjective, SoftmaxSumsToOneAndKeepsForbiddenAtZero) {
  const float z[4] = {1.0f, kForbidden, 0.5f, -2.0f};
  float p[4];
  Softmax(z, 4, p);
  EXPECT_NEAR(p[0] + p[1] + p[2] + p[3], 1.0f, 1e-6f);
  EXPECT_EQ(p[1], 0.0f);
  EXPECT_GT(p[0], p[2]);
}

}  // namespace
}  // namespace rlpos
