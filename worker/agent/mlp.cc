#include "worker/agent/mlp.h"

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
