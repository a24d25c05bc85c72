#include "worker/learning/agent/ue_set_module.h"

#include <algorithm>
#include <stdexcept>

#include "worker/learning/agent/mlp.h"

namespace rlpos {

UeSetModuleImpl::UeSetModuleImpl(int input_size, SlotBlock slots, const std::vector<int>& encoder,
                                 const std::vector<int>& hidden, int out)
    : slots_(slots) {
  if (encoder.empty())
    throw std::invalid_argument("UeSetModule: the encoder needs at least one layer");
  // phi: MakeMlp's layers with a ReLU after the last one too.
  const std::vector<int> inner(encoder.begin(), encoder.end() - 1);
  torch::nn::Sequential encoder_net = MakeMlp(inner, slots.width, encoder.back());
  encoder_net->push_back(torch::nn::ReLU());
  phi = register_module("phi", encoder_net);
  const int head_in = input_size - slots.count * slots.width + encoder.back();
  rho = register_module("rho", MakeMlp(hidden, head_in, out));
}

torch::Tensor UeSetModuleImpl::forward(const torch::Tensor& x) {
  const long rows = x.size(0);
  const long block = static_cast<long>(slots_.count) * slots_.width;
  const torch::Tensor slot_values =
      x.narrow(1, slots_.offset, block).reshape({rows, slots_.count, slots_.width});
  const torch::Tensor present = (slot_values.select(2, 0) > 0).to(torch::kFloat);  // [rows][count]
  const torch::Tensor encodings = phi->forward(slot_values);  // [rows][count][encoding]
  const torch::Tensor sums = (encodings * present.unsqueeze(2)).sum(1);
  const torch::Tensor mean = sums / present.sum(1, true).clamp_min(1.0);
  const long after = slots_.offset + block;
  const torch::Tensor head_in =
      torch::cat({x.narrow(1, 0, slots_.offset), mean, x.narrow(1, after, x.size(1) - after)}, 1);
  return rho->forward(head_in);
}

// Through DenseNetworks of phi's and rho's shapes, whose copies check the widths.
void CopyParameters(const UeSetModule& from, UeSetNetwork& to) {
  DenseNetwork encoder(to.EncoderSizes(), true);
  DenseNetwork head(to.HeadSizes());
  CopyParameters(from->phi, encoder);
  CopyParameters(from->rho, head);
  std::vector<float>& p = to.Parameters();
  std::copy(encoder.Parameters().begin(), encoder.Parameters().end(), p.begin());
  std::copy(head.Parameters().begin(), head.Parameters().end(),
            p.begin() + static_cast<long>(to.EncoderParameterCount()));
}

void CopyParameters(const UeSetNetwork& from, UeSetModule& to) {
  DenseNetwork encoder(from.EncoderSizes(), true);
  DenseNetwork head(from.HeadSizes());
  const std::vector<float>& p = from.Parameters();
  const auto split = p.begin() + static_cast<long>(from.EncoderParameterCount());
  std::copy(p.begin(), split, encoder.Parameters().begin());
  std::copy(split, p.end(), head.Parameters().begin());
  CopyParameters(encoder, to->phi);
  CopyParameters(head, to->rho);
}

std::optional<bool> SavedWithUeEncoder(const std::string& file) {
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(file);
  } catch (const c10::Error&) {
    return std::nullopt;
  }
  torch::serialize::InputArchive phi;
  return archive.try_read("phi", phi);
}

}  // namespace rlpos
