#include "worker/learning/agent_base/advantage_estimate.h"

#include <algorithm>

namespace rlpos {

AdvantageEstimate EstimateAdvantages(const std::vector<Transition>& rollout,
                                     const std::vector<int>& streams,
                                     const std::vector<float>& rewards,
                                     const std::vector<float>& values,
                                     const std::vector<float>& next_values, double gamma,
                                     double gae_lambda) {
  const std::size_t n = rollout.size();
  AdvantageEstimate out;
  out.advantages.resize(n);
  if (n == 0)
    return out;
  const int stream_count = 1 + *std::max_element(streams.begin(), streams.end());
  std::vector<float> carried_of(static_cast<std::size_t>(stream_count), 0.0f);
  std::vector<bool> seen(static_cast<std::size_t>(stream_count), false);
  for (std::size_t i = n; i-- > 0;) {
    const Transition& tr = rollout[i];
    const auto stream = static_cast<std::size_t>(streams[i]);
    float& carried = carried_of[stream];
    const float bootstrap = tr.terminal ? 0.0f : static_cast<float>(gamma) * next_values[i];
    const float delta = rewards[i] + bootstrap - values[i];
    if (tr.episode_end || !seen[stream])
      carried = 0.0f;
    seen[stream] = true;
    carried = delta + static_cast<float>(gamma * gae_lambda) * carried;
    out.advantages[i] = carried;
  }
  out.returns.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.returns[i] = out.advantages[i] + values[i];
  return out;
}

}  // namespace rlpos
