#pragma once
// The agent tests' training: plain, as the tiny envs (tiny_envs.h) were tuned for.
#include <cstdint>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// `algorithm` trained for `episodes` of the env's own, from its own start, with `seed`: no
// checkpoints, then one greedy evaluation episode. The algorithm's own settings are the caller's.
inline AgentSpec PlainTrainingSpec(const std::string& algorithm, std::uint64_t seed, int episodes) {
  AgentSpec spec;
  spec.algorithm = algorithm;
  spec.train_episodes = episodes;
  spec.eval_episodes = 1;
  spec.eval_interval = 0;
  spec.train_episode_steps = 0;
  spec.exploring_starts = false;
  spec.seed = seed;
  return spec;
}

}  // namespace rlpos
