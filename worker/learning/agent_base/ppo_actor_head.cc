#include "worker/learning/agent_base/ppo_actor_head.h"

#include <algorithm>
#include <stdexcept>

namespace rlpos {

void MaskLogits(const ActionMask& mask, int count, float* logits) {
  if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t a) { return a != 0; }))
    return;
  for (int a = 0; a < count; ++a) {
    if (!Allowed(mask, a))
      logits[a] += kForbiddenLogit;
  }
}

int MostProbableAllowed(const float* p, const ActionMask& mask, int count) {
  if (!mask.empty() && std::none_of(mask.begin(), mask.end(), [](std::uint8_t a) { return a; }))
    throw std::invalid_argument("the action mask allows no action");
  int action = -1;
  for (int a = 0; a < count; ++a) {
    if (Allowed(mask, a) && (action < 0 || p[a] > p[action]))
      action = a;
  }
  return action;
}

int SampleAllowed(const float* p, const ActionMask& mask, int count, double u) {
  int action = -1;
  double cumulative = 0.0;
  for (int a = 0; a < count; ++a) {
    if (!Allowed(mask, a) || p[a] <= 0.0f)
      continue;
    action = a;
    cumulative += p[a];
    if (u < cumulative)
      break;
  }
  return action;
}

}  // namespace rlpos
