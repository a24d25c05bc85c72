#include "worker/learning/agent/torchscript_policy.h"

#include <torch/script.h>

#include <cmath>
#include <stdexcept>

namespace rlpos {
namespace {

// libtorch's messages run over many lines (context, a C++ backtrace): the first says what.
std::string FirstLine(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "unknown error" : line;
}

std::string ShapeText(const at::Tensor& t) {
  std::string text = "[";
  for (int64_t i = 0; i < t.dim(); ++i)
    text += (i ? ", " : "") + std::to_string(t.size(i));
  return text + "]";
}

}  // namespace

struct TorchScriptPolicy::Module {
  torch::jit::Module module;
};

TorchScriptPolicy::TorchScriptPolicy(const std::string& file, int observation_dim, int action_count)
    : observation_dim_(observation_dim), action_count_(action_count) {
  try {
    module_ = std::make_unique<Module>(Module{torch::jit::load(file, torch::kCPU)});
  } catch (const c10::Error& e) {
    throw std::invalid_argument("does not load as a TorchScript module: " +
                                FirstLine(e.what_without_backtrace()));
  } catch (const std::exception& e) {
    throw std::invalid_argument("does not load as a TorchScript module: " + FirstLine(e.what()));
  }
  module_->module.eval();
  // Before any flight: a model of the wrong shape is refused with nothing run.
  Logits(std::vector<float>(static_cast<std::size_t>(observation_dim), 0.0f));
}

TorchScriptPolicy::~TorchScriptPolicy() = default;

std::vector<float> TorchScriptPolicy::Logits(const std::vector<float>& observation) const {
  const torch::InferenceMode inference;
  const at::Tensor input = torch::from_blob(const_cast<float*>(observation.data()),
                                            {1, observation_dim_}, torch::kFloat32);
  c10::IValue output;
  try {
    output = module_->module.forward({input});
  } catch (const c10::Error& e) {
    throw std::invalid_argument(
        "forward on a [1, " + std::to_string(observation_dim_) +
        "] float32 observation fails: " + FirstLine(e.what_without_backtrace()));
  } catch (const std::exception& e) {
    throw std::invalid_argument("forward on a [1, " + std::to_string(observation_dim_) +
                                "] float32 observation fails: " + FirstLine(e.what()));
  }
  const std::string expected = "[1, " + std::to_string(action_count_) + "] float logits";
  if (!output.isTensor())
    throw std::invalid_argument("forward returns a " + output.tagKind() + ", expected " + expected);
  const at::Tensor logits = output.toTensor();
  if (!logits.is_floating_point() || logits.dim() != 2 || logits.size(0) != 1 ||
      logits.size(1) != action_count_) {
    throw std::invalid_argument("forward returns " + std::string(logits.dtype().name()) + " " +
                                ShapeText(logits) + ", expected " + expected);
  }
  const at::Tensor values = logits.to(torch::kFloat32).contiguous();
  const float* v = values.data_ptr<float>();
  std::vector<float> out(v, v + action_count_);
  for (float x : out) {
    if (std::isnan(x))
      throw std::invalid_argument("forward returns NaN logits");
  }
  return out;
}

int TorchScriptPolicy::GreedyAction(const std::vector<float>& observation,
                                    const ActionMask& mask) const {
  const std::vector<float> logits = Logits(observation);
  int best = -1;
  for (int a = 0; a < action_count_; ++a) {
    if (Allowed(mask, a) && (best < 0 || logits[a] > logits[best]))
      best = a;
  }
  if (best < 0)
    throw std::invalid_argument("the action mask allows no action");
  return best;
}

}  // namespace rlpos
