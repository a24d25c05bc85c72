#include "worker/learning/agent_base/ppo_objective.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rlpos {

void Softmax(const float* logits, int count, float* p) {
  const float top = *std::max_element(logits, logits + count);
  double sum = 0.0;
  for (int a = 0; a < count; ++a) {
    p[a] = static_cast<float>(std::exp(static_cast<double>(logits[a] - top)));
    sum += p[a];
  }
  for (int a = 0; a < count; ++a)
    p[a] = static_cast<float>(p[a] / sum);
}

PpoObjective PpoLossAndGradients(const PpoMinibatch& batch, const PpoCoefficients& c) {
  const int rows = batch.rows;
  const int count = batch.action_count;
  if (rows <= 0 || count <= 0)
    throw std::invalid_argument("PpoLossAndGradients: an empty minibatch");
  // Standardised advantages (the sample standard deviation, as torch's std; 0 for one row).
  double mean = 0.0;
  for (int r = 0; r < rows; ++r)
    mean += batch.advantages[r];
  mean /= rows;
  double square_sum = 0.0;
  for (int r = 0; r < rows; ++r)
    square_sum += (batch.advantages[r] - mean) * (batch.advantages[r] - mean);
  const double deviation = rows > 1 ? std::sqrt(square_sum / (rows - 1)) : 0.0;

  PpoObjective out;
  out.d_logits.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(count), 0.0f);
  out.d_values.assign(static_cast<std::size_t>(rows), 0.0f);
  std::vector<double> log_p(static_cast<std::size_t>(count));
  std::vector<double> p(static_cast<std::size_t>(count));
  double surrogate_sum = 0.0;
  double entropy_sum = 0.0;
  double value_sum = 0.0;
  for (int r = 0; r < rows; ++r) {
    const float* z = batch.logits + static_cast<std::ptrdiff_t>(r) * count;
    // log-softmax
    const double top = *std::max_element(z, z + count);
    double sum = 0.0;
    for (int a = 0; a < count; ++a)
      sum += std::exp(z[a] - top);
    const double log_sum = top + std::log(sum);
    double entropy = 0.0;
    for (int a = 0; a < count; ++a) {
      log_p[static_cast<std::size_t>(a)] = z[a] - log_sum;
      p[static_cast<std::size_t>(a)] = std::exp(log_p[static_cast<std::size_t>(a)]);
      entropy -= p[static_cast<std::size_t>(a)] * log_p[static_cast<std::size_t>(a)];
    }
    const int taken = batch.actions[r];
    if (taken < 0 || taken >= count)
      throw std::invalid_argument("PpoLossAndGradients: an action outside the action space");
    const double advantage = (batch.advantages[r] - mean) / (deviation + 1e-8);
    const double ratio = std::exp(log_p[static_cast<std::size_t>(taken)] - batch.old_log_probs[r]);
    const double clipped = std::clamp(ratio, 1.0 - c.clip, 1.0 + c.clip);
    const double unclipped_term = -advantage * ratio;
    const double clipped_term = -advantage * clipped;
    surrogate_sum += std::max(unclipped_term, clipped_term);
    entropy_sum += entropy;
    const double value_error = batch.values[r] - batch.returns[r];
    value_sum += value_error * value_error;

    // d surrogate / d ratio: -A where the unclipped term is the larger (where they tie the ratio
    // is inside the clip range, and both halves of the gradient are -A); 0 where the clipped one
    // is (the clip is flat there).
    const double d_ratio = unclipped_term >= clipped_term ? -advantage : 0.0;
    const double d_taken = d_ratio * ratio;  // d log p(a): the ratio's own derivative
    float* dz = out.d_logits.data() + static_cast<std::ptrdiff_t>(r) * count;
    for (int a = 0; a < count; ++a) {
      const double pa = p[static_cast<std::size_t>(a)];
      // d log p(taken) / d z_a = [a == taken] - p_a;  d H / d z_a = -p_a (log p_a + H)
      const double d_log_taken = (a == taken ? 1.0 : 0.0) - pa;
      const double d_entropy =
          pa > 0.0 ? -pa * (log_p[static_cast<std::size_t>(a)] + entropy) : 0.0;
      dz[a] = static_cast<float>((d_taken * d_log_taken - c.entropy * d_entropy) / rows);
    }
    out.d_values[static_cast<std::size_t>(r)] = static_cast<float>(c.value * value_error / rows);
  }
  out.loss =
      surrogate_sum / rows - c.entropy * entropy_sum / rows + c.value * 0.5 * value_sum / rows;
  out.entropy = entropy_sum / rows;
  return out;
}

}  // namespace rlpos
