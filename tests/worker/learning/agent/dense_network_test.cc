// The plain-float network and Adam against libtorch, which they stand in for in PPO: the same
// outputs and gradients as torch's forward pass and autograd, the same Adam steps, and copies
// between the two that lose nothing.
#include "worker/learning/agent_base/dense_network.h"

#include <gtest/gtest.h>

#include <vector>

#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/mlp.h"
#include "worker/learning/agent_base/flat_adam.h"

namespace rlpos {
namespace {

constexpr int kIn = 5;
constexpr int kOut = 7;
const std::vector<int> kHidden{16, 12};

std::vector<float> FloatsOf(const torch::Tensor& t) {
  const torch::Tensor c = t.detach().contiguous();
  return std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
}

// A MakeMlp network and its DenseNetwork copy, with a batch of inputs where some hidden units
// are clipped by their ReLU.
struct Pair {
  torch::nn::Sequential torch_net = MakeMlp(kHidden, kIn, kOut);
  DenseNetwork dense{{kIn, 16, 12, kOut}};
  torch::Tensor x = torch::randn({9, kIn});

  Pair() { CopyParameters(torch_net, dense); }
};

TEST(DenseNetwork, ComputesWhatTheTorchNetworkComputes) {
  torch::manual_seed(3);
  Pair pair;
  std::vector<float> out(9 * kOut);
  pair.dense.Forward(FloatsOf(pair.x).data(), 9, out.data());
  const std::vector<float> expected = FloatsOf(pair.torch_net->forward(pair.x));
  ASSERT_EQ(out.size(), expected.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out[i], expected[i], 1e-5f) << "output " << i;
}

TEST(DenseNetwork, GradientsAreAutogradsWithinRounding) {
  torch::manual_seed(4);
  Pair pair;
  const torch::Tensor weights = torch::randn({9, kOut});  // loss = sum(weights * output)
  (pair.torch_net->forward(pair.x) * weights).sum().backward();
  std::vector<float> out(9 * kOut);
  pair.dense.Forward(FloatsOf(pair.x).data(), 9, out.data());
  pair.dense.Backward(FloatsOf(weights).data());

  // Torch's gradients, copied into the dense layout by the same copy as the parameters.
  torch::nn::Sequential grads = MakeMlp(kHidden, kIn, kOut);
  {
    torch::NoGradGuard no_grad;
    auto from = pair.torch_net->parameters();
    auto to = grads->parameters();
    for (std::size_t i = 0; i < from.size(); ++i)
      to[i].copy_(from[i].grad());
  }
  DenseNetwork expected({kIn, 16, 12, kOut});
  CopyParameters(grads, expected);
  const std::vector<float>& got = pair.dense.Gradients();
  ASSERT_EQ(got.size(), expected.Parameters().size());
  int nonzero = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i], expected.Parameters()[i], 1e-4f) << "gradient " << i;
    nonzero += got[i] != 0.0f;
  }
  EXPECT_GT(nonzero, static_cast<int>(got.size()) / 2);
}

// What a network in front of this one needs: the input's gradient (negative inputs included,
// which no ReLU made), and a ReLU on the output on request; the parameters' gradients unchanged.
TEST(DenseNetwork, GivesTheInputsGradientAndAnOutputReluOnRequest) {
  torch::manual_seed(7);
  Pair pair;
  torch::nn::Sequential relu_net = MakeMlp(kHidden, kIn, kOut);
  relu_net->push_back(torch::nn::ReLU());
  CopyParameters(pair.torch_net, relu_net);
  DenseNetwork dense({kIn, 16, 12, kOut}, true);
  CopyParameters(relu_net, dense);
  const torch::Tensor x = pair.x.clone().requires_grad_(true);
  const torch::Tensor weights = torch::randn({9, kOut});
  (relu_net->forward(x) * weights).sum().backward();

  std::vector<float> out(9 * kOut);
  dense.Forward(FloatsOf(x).data(), 9, out.data());
  const std::vector<float> expected_out = FloatsOf(relu_net->forward(x));
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out[i], expected_out[i], 1e-5f) << "output " << i;
  std::vector<float> d_input(9 * kIn);
  dense.Backward(FloatsOf(weights).data(), d_input.data());
  const std::vector<float> expected = FloatsOf(x.grad());
  int negative_inputs = 0;
  for (std::size_t i = 0; i < d_input.size(); ++i) {
    EXPECT_NEAR(d_input[i], expected[i], 1e-4f) << "input " << i;
    negative_inputs += FloatsOf(x)[i] < 0.0f && expected[i] != 0.0f;
  }
  EXPECT_GT(negative_inputs, 0);
  const std::vector<float> with_input = dense.Gradients();
  dense.Backward(FloatsOf(weights).data());
  EXPECT_EQ(dense.Gradients(), with_input);
}

TEST(DenseNetwork, CopiesToTorchAndBackLoseNothing) {
  torch::manual_seed(5);
  Pair pair;
  for (std::size_t i = 0; i < pair.dense.Parameters().size(); ++i)
    pair.dense.Parameters()[i] = 0.001f * static_cast<float>(i) - 0.3f;
  torch::nn::Sequential back = MakeMlp(kHidden, kIn, kOut);
  CopyParameters(pair.dense, back);
  DenseNetwork again({kIn, 16, 12, kOut});
  CopyParameters(back, again);
  EXPECT_EQ(again.Parameters(), pair.dense.Parameters());
  DenseNetwork narrower({kIn, 16, kOut});
  EXPECT_THROW(CopyParameters(back, narrower), std::invalid_argument);
}

TEST(DenseNetwork, RefusesShapesWithoutLayers) {
  EXPECT_THROW(DenseNetwork({4}), std::invalid_argument);
  EXPECT_THROW(DenseNetwork({4, 0, 2}), std::invalid_argument);
}

// Bit for bit with libtorch's baseline kernels, the ones a training pins.
TEST(FlatAdam, StepsExactlyAsTorchAdam) {
  torch::manual_seed(6);
  torch::Tensor p = torch::randn({50}).requires_grad_(true);
  torch::optim::Adam torch_adam({p}, torch::optim::AdamOptions(3e-3).eps(1e-5));
  std::vector<float> flat = FloatsOf(p);
  FlatAdam adam(flat.size(), 3e-3, 1e-5);
  for (int step = 0; step < 20; ++step) {
    const torch::Tensor g = torch::randn({50}) * (step + 1);
    p.mutable_grad() = g.clone();
    torch_adam.step();
    adam.Step(flat, FloatsOf(g));
    ASSERT_EQ(flat, FloatsOf(p))
        << "after step " << step + 1
        << " (with ATEN_CPU_CAPABILITY=default, as ctest runs it: libtorch's native kernels fuse "
           "multiply-adds)";
  }
  adam.SetLearningRate(1e-4);
  EXPECT_DOUBLE_EQ(adam.LearningRate(), 1e-4);
}

}  // namespace
}  // namespace rlpos
