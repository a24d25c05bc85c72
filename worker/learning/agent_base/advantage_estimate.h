#pragma once
// PPO's advantages by GAE(lambda) over a rollout that several envs collected, and the returns
// (advantages + values). Plain float, compiled as PPO's other arithmetic (CMakeLists.txt).
#include <vector>

#include "worker/learning/agent_base/replay_buffer.h"

namespace rlpos {

struct AdvantageEstimate {
  std::vector<float> advantages;
  std::vector<float> returns;
};

// rewards[i], values[i] and next_values[i] belong to rollout[i], collected by env streams[i]
// (0, 1, ...). A terminal transition bootstraps from 0, a truncated one from its next value; no
// advantage is carried across an episode's end, nor from one env's transitions to another's (the
// last of each env's is cut as the rollout's).
AdvantageEstimate EstimateAdvantages(const std::vector<Transition>& rollout,
                                     const std::vector<int>& streams,
                                     const std::vector<float>& rewards,
                                     const std::vector<float>& values,
                                     const std::vector<float>& next_values, double gamma,
                                     double gae_lambda);

}  // namespace rlpos
