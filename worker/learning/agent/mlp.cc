#include "worker/learning/agent/mlp.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace rlpos {

torch::nn::Sequential MakeMlp(const std::vector<int>& hidden, int in, int out) {
  torch::nn::Sequential net;
  int width = in;
  for (int units : hidden) {
    net->push_back(torch::nn::Linear(width, units));
    net->push_back(torch::nn::ReLU());
    width = units;
  }
  net->push_back(torch::nn::Linear(width, out));
  return net;
}

void CopyParameters(const torch::nn::Sequential& from, torch::nn::Sequential& to) {
  torch::NoGradGuard no_grad;
  auto source = from->parameters();
  auto target = to->parameters();
  for (std::size_t i = 0; i < source.size(); ++i)
    target[i].copy_(source[i]);
}

namespace {

// The Linear layers of a MakeMlp network, checked against a DenseNetwork's widths.
std::vector<torch::nn::Linear> LinearLayers(const torch::nn::Sequential& net,
                                            const DenseNetwork& dense) {
  std::vector<torch::nn::Linear> layers;
  for (const auto& module : net->children()) {
    if (auto linear = std::dynamic_pointer_cast<torch::nn::LinearImpl>(module))
      layers.emplace_back(linear);
  }
  bool same = static_cast<int>(layers.size()) == dense.LayerCount();
  for (int l = 0; same && l < dense.LayerCount(); ++l) {
    const auto& w = layers[static_cast<std::size_t>(l)]->weight;
    same = w.size(0) == dense.LayerOutputs(l) && w.size(1) == dense.LayerInputs(l);
  }
  if (!same)
    throw std::invalid_argument("a torch network and a dense network of other widths");
  return layers;
}

}  // namespace

void CopyParameters(const torch::nn::Sequential& from, DenseNetwork& to) {
  const auto layers = LinearLayers(from, to);
  for (int l = 0; l < to.LayerCount(); ++l) {
    const torch::Tensor w = layers[static_cast<std::size_t>(l)]->weight.detach().contiguous();
    const torch::Tensor b = layers[static_cast<std::size_t>(l)]->bias.detach().contiguous();
    to.SetLayer(l, w.data_ptr<float>(), b.data_ptr<float>());
  }
}

void CopyParameters(const DenseNetwork& from, torch::nn::Sequential& to) {
  const auto layers = LinearLayers(to, from);
  const std::vector<float>& p = from.Parameters();
  torch::NoGradGuard no_grad;
  for (int l = 0; l < from.LayerCount(); ++l) {
    const int in = from.LayerInputs(l);
    const int out = from.LayerOutputs(l);
    torch::Tensor w = torch::empty({out, in});
    auto wa = w.accessor<float, 2>();
    for (int i = 0; i < in; ++i) {
      for (int o = 0; o < out; ++o)
        wa[o][i] = p[from.WeightOffset(l) + static_cast<std::size_t>(i * out + o)];
    }
    torch::Tensor b = torch::empty({out});
    std::copy(p.begin() + static_cast<long>(from.BiasOffset(l)),
              p.begin() + static_cast<long>(from.BiasOffset(l)) + out, b.data_ptr<float>());
    layers[static_cast<std::size_t>(l)]->weight.copy_(w);
    layers[static_cast<std::size_t>(l)]->bias.copy_(b);
  }
}

void KeptNetworks::Keep(const std::vector<torch::nn::Sequential>& networks) {
  torch::NoGradGuard no_grad;
  parameters_.clear();
  for (const auto& net : networks) {
    std::vector<torch::Tensor> copies;
    for (const auto& p : net->parameters())
      copies.push_back(p.detach().clone());
    parameters_.push_back(std::move(copies));
  }
}

void KeptNetworks::Restore(const std::vector<torch::nn::Sequential>& networks) const {
  if (parameters_.size() != networks.size())
    throw std::logic_error("no policy kept to restore");
  torch::NoGradGuard no_grad;
  for (std::size_t n = 0; n < networks.size(); ++n) {
    auto target = networks[n]->parameters();
    for (std::size_t i = 0; i < target.size(); ++i)
      target[i].copy_(parameters_[n][i]);
  }
}

void SoftUpdate(const torch::nn::Sequential& from, torch::nn::Sequential& to, double tau) {
  torch::NoGradGuard no_grad;
  auto source = from->parameters();
  auto target = to->parameters();
  for (std::size_t i = 0; i < source.size(); ++i)
    target[i].mul_(1.0 - tau).add_(source[i], tau);
}

torch::Tensor Row(const std::vector<float>& values) {
  return torch::from_blob(const_cast<float*>(values.data()), {1, static_cast<long>(values.size())},
                          torch::kFloat)
      .clone();
}

torch::Tensor MaskPenalty(const std::vector<const ActionMask*>& masks, int actions,
                          float forbidden) {
  torch::Tensor penalty = torch::zeros({static_cast<long>(masks.size()), actions});
  auto p = penalty.accessor<float, 2>();
  for (std::size_t r = 0; r < masks.size(); ++r) {
    const ActionMask& mask = *masks[r];
    if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; }))
      continue;
    for (int a = 0; a < actions; ++a) {
      if (!Allowed(mask, a))
        p[static_cast<long>(r)][a] = forbidden;
    }
  }
  return penalty;
}

void LoadNetwork(const std::string& file, torch::nn::Sequential& into,
                 const std::vector<int>& hidden, int in, int out) {
  if (!std::filesystem::exists(file))
    throw std::runtime_error(file + ": no such policy file");
  // Loaded into a scratch network first: torch::load takes any tensor shapes it finds.
  torch::nn::Sequential loaded = MakeMlp(hidden, in, out);
  try {
    torch::load(loaded, file);
  } catch (const c10::Error&) {
    throw std::runtime_error(file + ": not a policy file of this network");
  }
  const auto expected = into->parameters();
  const auto got = loaded->parameters();
  bool same = got.size() == expected.size();
  for (std::size_t i = 0; same && i < got.size(); ++i)
    same = got[i].sizes() == expected[i].sizes();
  if (!same) {
    throw std::runtime_error(file +
                             ": the policy's network shape differs from the scenario's "
                             "(observations, actions or agent.hidden changed)");
  }
  CopyParameters(loaded, into);
}

}  // namespace rlpos
