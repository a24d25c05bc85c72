#pragma once
// The agent of spec.algorithm, sized for an env's spaces.
#include <memory>

#include "agent/agent.h"
#include "gym/env.h"
#include "scenario/scenario.h"

namespace rlpos {

// Throws std::invalid_argument when the algorithm does not fit the env's action space.
std::unique_ptr<Agent> MakeAgent(const AgentSpec& spec, const Env& env);

}  // namespace rlpos
