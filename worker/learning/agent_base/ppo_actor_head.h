#pragma once
// What PPO's actor does with its network's logits, shared by the training agent (ppo_agent.h)
// and the greedy policy that flies without libtorch (ppo_greedy_policy.h), so that both choose
// the same action from the same logits.
#include "worker/env/gym/spaces.h"

namespace rlpos {

// The logit of the actions a mask forbids: their probability is 0, and unlike -inf it keeps
// 0 * log(0) in the entropy finite.
constexpr float kForbiddenLogit = -1e9f;

// Adds kForbiddenLogit to the logits of the `count` actions `mask` forbids; a mask that allows
// nothing counts as no mask.
void MaskLogits(const ActionMask& mask, int count, float* logits);

// The most probable action `mask` allows (the lowest index among equals). std::invalid_argument
// when the mask allows nothing.
int MostProbableAllowed(const float* p, const ActionMask& mask, int count);
// The allowed action whose share of the cumulative probabilities holds `u` (in [0, 1)): a sample
// by inverse CDF, actions of probability 0 skipped; the last allowed action takes what rounding
// leaves over. -1 when the mask allows nothing with a probability above 0.
int SampleAllowed(const float* p, const ActionMask& mask, int count, double u);

}  // namespace rlpos
