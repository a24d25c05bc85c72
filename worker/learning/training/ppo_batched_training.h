#pragma once
// PPO trained on agent.ppo.num_envs analytic envs at once: a BatchedEnv collects each rollout,
// with one forward pass of the policy for all the envs per step. The training episodes are
// Train's (the same seeds, exploring starts and step limit), flown in rounds of num_envs: env
// i of round k flies episode k * num_envs + i. Checkpoints, early stopping and the evaluation
// are Train's, on one env of the scenario, after the round in which their episode falls. The
// result does not depend on the batched env's thread count; with num_envs = 1 it is Train's.
#include <cstddef>
#include <cstdint>

#include "common/scenario/scenario.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {

// Trains `agent` (built for `scenario`'s spaces and scenario.agent) from episode run `seed` on
// scenario.agent.ppo.num_envs envs, stepped over `threads` threads (0: min(cores, num_envs)).
// std::invalid_argument for a scenario the batched env refuses (packet fidelity), or several
// UAVs with agent.joint_steps.
TrainResult TrainPpoBatched(const Scenario& scenario, PpoAgent& agent, std::uint64_t seed,
                            std::size_t threads = 0, const EpisodeCallback& on_episode = nullptr,
                            const StepCallback& on_eval_step = nullptr);

}  // namespace rlpos
