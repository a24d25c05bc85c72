#include "worker/learning/agent/ppo_network.h"

#include <filesystem>
#include <stdexcept>

#include "worker/learning/agent/mlp.h"

namespace rlpos {
namespace {

std::vector<int> Widths(int in, const std::vector<int>& hidden, int out) {
  std::vector<int> widths{in};
  widths.insert(widths.end(), hidden.begin(), hidden.end());
  widths.push_back(out);
  return widths;
}

}  // namespace

PpoNetwork::PpoNetwork(int in, const std::vector<int>& hidden, int out,
                       const std::vector<int>& ue_encoder, const std::optional<SlotBlock>& ue_slots)
    : in_(in), hidden_(hidden), out_(out), ue_encoder_(ue_encoder) {
  if (ue_encoder.empty()) {
    mlp_ = std::make_unique<DenseNetwork>(Widths(in, hidden, out));
    mlp_torch_ = MakeMlp(hidden, in, out);
    CopyParameters(mlp_torch_, *mlp_);
    return;
  }
  if (!ue_slots)
    throw std::invalid_argument("agent.ue_encoder needs \"ues\" in env.observations");
  ue_slots_ = *ue_slots;
  set_ = std::make_unique<UeSetNetwork>(in, ue_slots_, ue_encoder, hidden, out);
  set_torch_ = UeSetModule(in, ue_slots_, ue_encoder, hidden, out);
  CopyParameters(set_torch_, *set_);
}

void PpoNetwork::Forward(const float* x, int rows, float* out) {
  if (set_)
    set_->Forward(x, rows, out);
  else
    mlp_->Forward(x, rows, out);
}

void PpoNetwork::Backward(const float* d_out) {
  if (set_)
    set_->Backward(d_out);
  else
    mlp_->Backward(d_out);
}

std::vector<float>& PpoNetwork::Parameters() {
  return set_ ? set_->Parameters() : mlp_->Parameters();
}

const std::vector<float>& PpoNetwork::Parameters() const {
  return set_ ? static_cast<const UeSetNetwork&>(*set_).Parameters() : mlp_->Parameters();
}

std::vector<float>& PpoNetwork::Gradients() {
  return set_ ? set_->Gradients() : mlp_->Gradients();
}

void PpoNetwork::Save(const std::string& file) {
  if (set_) {
    CopyParameters(*set_, set_torch_);
    torch::save(set_torch_, file);
  } else {
    CopyParameters(*mlp_, mlp_torch_);
    torch::save(mlp_torch_, file);
  }
}

void PpoNetwork::Load(const std::string& file) {
  if (set_) {
    LoadSet(file);
    return;
  }
  try {
    LoadNetwork(file, mlp_torch_, hidden_, in_, out_);
  } catch (const std::runtime_error&) {
    if (SavedWithUeEncoder(file).value_or(false)) {
      throw std::runtime_error(file +
                               ": the policy's network has a UE encoder (agent.ue_encoder), "
                               "the scenario's agent has none");
    }
    throw;
  }
  CopyParameters(mlp_torch_, *mlp_);
}

void PpoNetwork::LoadSet(const std::string& file) {
  if (!std::filesystem::exists(file))
    throw std::runtime_error(file + ": no such policy file");
  const std::optional<bool> with_encoder = SavedWithUeEncoder(file);
  if (!with_encoder)
    throw std::runtime_error(file + ": not a policy file of this network");
  if (!*with_encoder) {
    throw std::runtime_error(file +
                             ": the policy's network has no UE encoder, the scenario's agent "
                             "sets agent.ue_encoder");
  }
  const std::string other_shape =
      file +
      ": the policy's network shape differs from the scenario's (observations, actions, "
      "agent.hidden or agent.ue_encoder changed)";
  // Loaded into a scratch module first: torch::load takes any tensor shapes it finds.
  UeSetModule loaded(in_, ue_slots_, ue_encoder_, hidden_, out_);
  try {
    torch::load(loaded, file);
  } catch (const c10::Error&) {
    throw std::runtime_error(other_shape);  // other layer counts: parameters it lacks
  }
  const auto expected = set_torch_->parameters();
  const auto got = loaded->parameters();
  bool same = got.size() == expected.size();
  for (std::size_t i = 0; same && i < got.size(); ++i)
    same = got[i].sizes() == expected[i].sizes();
  if (!same)
    throw std::runtime_error(other_shape);
  CopyParameters(loaded, *set_);
}

}  // namespace rlpos
