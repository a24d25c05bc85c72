// The UE set network (agent.ue_encoder) against its libtorch twin, which initialises, saves and
// loads it: the same outputs and gradients as torch's forward pass and autograd, copies that lose
// nothing, and an output that takes the UE slots as a set.
#include "worker/learning/agent_base/ue_set_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "worker/learning/agent/libtorch.h"
#include "worker/learning/agent/ue_set_module.h"

namespace rlpos::ue_set_network_test {
namespace {

// 3 values, 5 UE slots of 7, 2 values: slots between other values, as in an observation.
constexpr int kIn = 3 + 5 * 7 + 2;
constexpr SlotBlock kSlots{3, 5, 7};
constexpr int kOut = 6;
const std::vector<int> kEncoder{12, 8};
const std::vector<int> kHidden{16, 10};
constexpr int kRows = 6;

std::vector<float> FloatsOf(const torch::Tensor& t) {
  const torch::Tensor c = t.detach().contiguous();
  return std::vector<float>(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
}

float* SlotOf(std::vector<float>& x, int row, int slot) {
  return x.data() + row * kIn + kSlots.offset + slot * kSlots.width;
}

// Random observations whose slots are present (first value 1) or empty (all -1, as a normalised
// empty slot is), some of each in most rows; row 0 has every slot empty, row 1 every one present.
std::vector<float> Observations(std::uint32_t seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::vector<float> x(kRows * kIn);
  for (float& v : x)
    v = value(g);
  for (int r = 0; r < kRows; ++r) {
    for (int k = 0; k < kSlots.count; ++k) {
      float* slot = SlotOf(x, r, k);
      const bool present = r == 1 || (r != 0 && (g() % 3 != 0));
      if (present)
        slot[0] = 1.0f;
      else
        std::fill(slot, slot + kSlots.width, -1.0f);
    }
  }
  return x;
}

// A twin pair: the module as libtorch initialises it, and the network given its parameters.
struct Twins {
  UeSetModule module{kIn, kSlots, kEncoder, kHidden, kOut};
  UeSetNetwork net{kIn, kSlots, kEncoder, kHidden, kOut};
  Twins() { CopyParameters(module, net); }

  std::vector<float> Forward(const std::vector<float>& x) {
    std::vector<float> out(x.size() / kIn * kOut);
    net.Forward(x.data(), static_cast<int>(x.size() / kIn), out.data());
    return out;
  }
};

torch::Tensor TensorOf(const std::vector<float>& x) {
  return torch::tensor(x).reshape({static_cast<long>(x.size()) / kIn, kIn});
}

TEST(UeSetNetwork, ComputesWhatItsTorchTwinComputes) {
  torch::manual_seed(3);
  Twins twins;
  const std::vector<float> x = Observations(3);
  const std::vector<float> out = twins.Forward(x);
  const std::vector<float> expected = FloatsOf(twins.module->forward(TensorOf(x)));
  ASSERT_EQ(out.size(), expected.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out[i], expected[i], 1e-5f) << "output " << i;
}

TEST(UeSetNetwork, GradientsAreAutogradsWithinRounding) {
  torch::manual_seed(4);
  Twins twins;
  const std::vector<float> x = Observations(4);
  const torch::Tensor weights = torch::randn({kRows, kOut});  // loss = sum(weights * output)
  (twins.module->forward(TensorOf(x)) * weights).sum().backward();
  twins.Forward(x);
  twins.net.Backward(FloatsOf(weights).data());

  // Torch's gradients, in the network's layout by the same copy as the parameters.
  UeSetModule grads(kIn, kSlots, kEncoder, kHidden, kOut);
  {
    torch::NoGradGuard no_grad;
    auto from = twins.module->parameters();
    auto to = grads->parameters();
    ASSERT_EQ(from.size(), to.size());
    for (std::size_t i = 0; i < from.size(); ++i)
      to[i].copy_(from[i].grad());
  }
  UeSetNetwork expected(kIn, kSlots, kEncoder, kHidden, kOut);
  CopyParameters(grads, expected);
  const std::vector<float>& got = twins.net.Gradients();
  ASSERT_EQ(got.size(), expected.Parameters().size());
  int nonzero_encoder = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const float e = expected.Parameters()[i];
    EXPECT_NEAR(got[i], e, 1e-4f * std::max(1.0f, std::abs(e))) << "gradient " << i;
    if (i < twins.net.EncoderParameterCount())
      nonzero_encoder += got[i] != 0.0f;
  }
  // The encoder learns: its gradients come through the mean.
  EXPECT_GT(nonzero_encoder, static_cast<int>(twins.net.EncoderParameterCount()) / 2);
}

TEST(UeSetNetwork, TakesTheSlotsAsASet) {
  torch::manual_seed(5);
  Twins twins;
  const std::vector<float> x = Observations(5);
  const std::vector<float> out = twins.Forward(x);

  // Each row's slots shuffled: present ones reordered, empty ones moved among them.
  std::vector<float> shuffled = x;
  std::mt19937 g(5);
  for (int r = 0; r < kRows; ++r) {
    std::vector<std::vector<float>> slots;
    for (int k = 0; k < kSlots.count; ++k)
      slots.emplace_back(SlotOf(shuffled, r, k), SlotOf(shuffled, r, k) + kSlots.width);
    std::shuffle(slots.begin(), slots.end(), g);
    std::reverse(slots.begin(), slots.end());  // never the same order
    for (int k = 0; k < kSlots.count; ++k)
      std::copy(slots[k].begin(), slots[k].end(), SlotOf(shuffled, r, k));
  }
  ASSERT_NE(shuffled, x);
  const std::vector<float> out_shuffled = twins.Forward(shuffled);
  for (std::size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out_shuffled[i], out[i], 1e-6f) << "output " << i;

  // One present slot's values changed: its row's output changes, the others' do not.
  std::vector<float> changed = x;
  SlotOf(changed, 1, 2)[1] += 0.5f;
  SlotOf(changed, 1, 2)[4] -= 0.5f;
  const std::vector<float> out_changed = twins.Forward(changed);
  float moved = 0.0f;
  for (int o = 0; o < kOut; ++o)
    moved = std::max(moved, std::abs(out_changed[kOut + o] - out[kOut + o]));
  EXPECT_GT(moved, 1e-4f);
  for (std::size_t i = 2 * kOut; i < out.size(); ++i)
    EXPECT_EQ(out_changed[i], out[i]) << "output " << i;

  // An empty slot's values do not matter.
  std::vector<float> empty_changed = x;
  SlotOf(empty_changed, 0, 3)[2] = 0.7f;
  EXPECT_EQ(twins.Forward(empty_changed), out);
}

TEST(UeSetNetwork, CopiesToTorchAndBackLoseNothing) {
  torch::manual_seed(6);
  Twins twins;
  for (std::size_t i = 0; i < twins.net.Parameters().size(); ++i)
    twins.net.Parameters()[i] = 0.001f * static_cast<float>(i % 700) - 0.3f;
  UeSetModule back(kIn, kSlots, kEncoder, kHidden, kOut);
  CopyParameters(twins.net, back);
  UeSetNetwork again(kIn, kSlots, kEncoder, kHidden, kOut);
  CopyParameters(back, again);
  EXPECT_EQ(again.Parameters(), twins.net.Parameters());
  UeSetNetwork narrower(kIn, kSlots, {12}, kHidden, kOut);
  EXPECT_THROW(CopyParameters(back, narrower), std::invalid_argument);
}

TEST(UeSetNetwork, RefusesSlotsOutsideTheInputAndNoEncoder) {
  EXPECT_THROW(UeSetNetwork(kIn, SlotBlock{10, 5, 7}, kEncoder, kHidden, kOut),
               std::invalid_argument);
  EXPECT_THROW(UeSetNetwork(kIn, kSlots, {}, kHidden, kOut), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos::ue_set_network_test
