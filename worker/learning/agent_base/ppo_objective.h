#pragma once
// PPO's minibatch loss and its gradient with respect to the actor's logits and the critic's
// values, by hand (no autograd): the clipped surrogate, the entropy bonus and the value loss, as
// CleanRL's ppo.py writes them,
//   loss = mean(max(-A r, -A clip(r, 1 - c, 1 + c))) - c_e mean(H) + c_v 0.5 mean((v - R)^2),
// with r = exp(log p(a) - old log p(a)) and A the advantages standardised over the minibatch.
#include <cstdint>
#include <vector>

namespace rlpos {

struct PpoMinibatch {
  int rows = 0;
  int action_count = 0;
  const float* logits = nullptr;  // [rows][action_count], forbidden actions already penalised
  const float* values = nullptr;  // [rows], the critic's
  const int* actions = nullptr;   // [rows], the actions taken
  const float* old_log_probs = nullptr;  // [rows], of the actions taken, when they were taken
  const float* advantages = nullptr;     // [rows], before standardisation
  const float* returns = nullptr;        // [rows]
};

struct PpoCoefficients {
  double clip = 0.2;
  double entropy = 0.01;
  double value = 0.5;
};

struct PpoObjective {
  double loss = 0.0;
  double entropy = 0.0;  // the rows' mean policy entropy: a figure to show (loss holds its term)
  std::vector<float> d_logits;  // [rows][action_count]
  std::vector<float> d_values;  // [rows]
};

PpoObjective PpoLossAndGradients(const PpoMinibatch& batch, const PpoCoefficients& c);

// Softmax of one row of logits into p (the max subtracted first).
void Softmax(const float* logits, int count, float* p);

}  // namespace rlpos
