#pragma once
// The agent of spec.algorithm, sized for an env's spaces.
#include <cstdint>
#include <memory>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/learning/agent_base/agent.h"

namespace rlpos {

// Throws std::invalid_argument when the algorithm does not fit the env's action space.
// training_steps: the env steps it will learn from (PPO's learning-rate annealing spans them;
// 0 for an agent that will only act, or when unknown: no annealing).
std::unique_ptr<Agent> MakeAgent(const AgentSpec& spec, const Env& env,
                                 std::int64_t training_steps = 0);

}  // namespace rlpos
