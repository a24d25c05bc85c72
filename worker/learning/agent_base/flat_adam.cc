#include "worker/learning/agent_base/flat_adam.h"

#include <cmath>
#include <stdexcept>

#include "worker/learning/agent_base/state_stream.h"

namespace rlpos {

FlatAdam::FlatAdam(std::size_t size, double learning_rate, double eps, double beta1, double beta2)
    : learning_rate_(learning_rate),
      eps_(eps),
      beta1_(beta1),
      beta2_(beta2),
      first_moment_(size, 0.0f),
      second_moment_(size, 0.0f) {}

void FlatAdam::Step(std::vector<float>& parameters, const std::vector<float>& gradients) {
  if (parameters.size() != first_moment_.size() || gradients.size() != first_moment_.size())
    throw std::invalid_argument("FlatAdam::Step: parameters and gradients of another size");
  ++steps_;
  const double bias_correction1 = 1.0 - std::pow(beta1_, static_cast<double>(steps_));
  const double bias_correction2 = 1.0 - std::pow(beta2_, static_cast<double>(steps_));
  // As libtorch: scalars rounded to float, then float arithmetic element by element.
  const float beta1 = static_cast<float>(beta1_);
  const float one_minus_beta1 = static_cast<float>(1.0 - beta1_);
  const float beta2 = static_cast<float>(beta2_);
  const float one_minus_beta2 = static_cast<float>(1.0 - beta2_);
  const float root_correction2 = static_cast<float>(std::sqrt(bias_correction2));
  const float eps = static_cast<float>(eps_);
  const float step = static_cast<float>(-learning_rate_ / bias_correction1);
  float* p = parameters.data();
  const float* g = gradients.data();
  float* m = first_moment_.data();
  float* v = second_moment_.data();
  const std::size_t n = parameters.size();
  for (std::size_t i = 0; i < n; ++i) {
    m[i] = m[i] * beta1 + g[i] * one_minus_beta1;
    v[i] = v[i] * beta2 + one_minus_beta2 * g[i] * g[i];
    const float denom = std::sqrt(v[i]) / root_correction2 + eps;
    p[i] = p[i] + step * m[i] / denom;
  }
}

void FlatAdam::SaveState(std::ostream& out) const {
  state::Write(out, learning_rate_);
  state::Write(out, steps_);
  state::WriteVector(out, first_moment_);
  state::WriteVector(out, second_moment_);
}

void FlatAdam::LoadState(std::istream& in) {
  learning_rate_ = state::Read<double>(in);
  steps_ = state::Read<std::int64_t>(in);
  const std::size_t n = first_moment_.size();
  state::ReadVector(in, first_moment_, n, "Adam's first moments");
  state::ReadVector(in, second_moment_, n, "Adam's second moments");
}

}  // namespace rlpos
