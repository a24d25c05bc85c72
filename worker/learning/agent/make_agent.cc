#include "worker/learning/agent/make_agent.h"

#include <stdexcept>

#include "worker/learning/agent/dqn_agent.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/agent/sac_agent.h"

namespace rlpos {

std::unique_ptr<Agent> MakeAgent(const AgentSpec& spec, const Env& env,
                                 std::int64_t training_steps) {
  const int observations = static_cast<int>(env.ObservationSpace().Dim());
  const int continuous = static_cast<int>(env.ContinuousActionSpace().Dim());
  const int discrete = env.ActionSpace().n;
  if (spec.algorithm == "sac") {
    if (continuous == 0)
      throw std::invalid_argument("sac needs a continuous action space");
    return std::make_unique<SacAgent>(spec, observations, continuous);
  }
  if (discrete == 0)
    throw std::invalid_argument(spec.algorithm + " needs a discrete action space");
  if (spec.algorithm == "ppo")
    return std::make_unique<PpoAgent>(spec, observations, discrete, training_steps, env.UeSlots());
  if (spec.algorithm == "dqn")
    return std::make_unique<DqnAgent>(spec, observations, discrete);
  throw std::invalid_argument("unknown algorithm " + spec.algorithm);
}

}  // namespace rlpos
