#pragma once
// The end of a greedy episode without flying all of it. A greedy agent acts as a function of its
// observation, so when the env can tell the state its future follows from (Env::Determining),
// the flight is periodic from the first state it meets again: its end is read off the cycle.
// With one UAV a flight usually settles within a few dozen of the env's 1,000 steps.
#include <cstdint>

#include "worker/agent/agent.h"
#include "worker/agent/trainer.h"
#include "worker/gym/env.h"

namespace rlpos {

struct GreedyFlight {
  StepInfo final_info;      // the info at the episode's end, as RunEpisode gives it
  double final_reward = 0;  // the reward of its last step
  int steps = 0;            // the episode's steps
  int steps_flown = 0;      // of which flown: the rest repeat a cycle
};

// RunEpisode(env, agent, seed, false, nullptr, options)'s final_info and final_reward, bit for
// bit, also with options.joint (every UAV moving at once). Flies the whole episode when the env
// cannot tell its state.
GreedyFlight FlyGreedy(Env& env, Agent& agent, std::uint64_t seed, const EpisodeOptions& options);

}  // namespace rlpos
