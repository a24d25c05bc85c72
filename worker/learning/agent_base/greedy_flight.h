#pragma once
// The end of a greedy episode without flying all of it. A greedy agent acts as a function of its
// observation, so when the env can tell the state its future follows from (Env::Determining),
// the flight is periodic from the first state it meets again: its end is read off the cycle.
// With one UAV a flight usually settles within a few dozen of the env's 1,000 steps.
#include <cstdint>

#include "worker/env/gym/env.h"
#include "worker/learning/agent_base/agent.h"
#include "worker/learning/agent_base/trainer.h"

namespace rlpos {

// FlyGreedy's; FlyGreedyToBest's means its best step where this says the episode's end.
struct GreedyFlight {
  StepInfo final_info;      // the info at the episode's end, as RunEpisode gives it
  double final_reward = 0;  // the reward of its last step
  int steps = 0;            // the episode's steps
  int steps_flown = 0;      // of which flown: the rest repeat a cycle
  int best_step = 0;        // FlyGreedyToBest: the step (from 1) that reached final_info
};

// RunEpisode(env, agent, seed, false, nullptr, options)'s final_info and final_reward, bit for
// bit, also with options.joint (every UAV moving at once). Flies the whole episode when the env
// cannot tell its state.
GreedyFlight FlyGreedy(Env& env, Agent& agent, std::uint64_t seed, const EpisodeOptions& options);

// The best placement the same greedy flight reaches (where a policy for any scenario places its
// UAVs): final_info and final_reward are those of the step with the highest reward, the first of
// equals. A policy that keeps moving once it is near the best (several UAVs, each acting on what
// the others just did) would otherwise end wherever the episode's last step leaves it, after up
// to a thousand steps. The flight stops once `patience_steps` steps bring no higher reward (0: no
// such stop), once it meets a state again (nothing after it is new), or at the episode's end;
// `steps` and `steps_flown` are the steps flown.
GreedyFlight FlyGreedyToBest(Env& env, Agent& agent, std::uint64_t seed,
                             const EpisodeOptions& options, int patience_steps);

// The best of up to `flights` FlyGreedyToBest flights of one greedy policy: the first from the
// usual start (options.reset), flight k (k = 1, 2, ...) from a start drawn from seed + k
// (ResetOptions::random_start), flown only while fewer than `step_budget` steps have been flown
// and cut at the steps left. The cost of a placement is then at most the first flight's or the
// budget, whichever is more. final_info, final_reward and best_step are the best flight's (the
// first of equals); steps and steps_flown count every flight's steps. Throws
// std::invalid_argument for flights < 1.
GreedyFlight FlyGreedyFromStarts(Env& env, Agent& agent, std::uint64_t seed,
                                 const EpisodeOptions& options, int patience_steps, int flights,
                                 int step_budget);

// The patience of a policy for any scenario's flight (its placement, each decision of a
// tracking run, its validation in training), chosen on scripts/generate_scenario_set.sh's
// tune-many and tune sets (docs/any-scenario.md, best of the flight): long enough for one UAV's way
// round a building, in which the reward may not rise.
constexpr int kGeneralPatienceSteps = 60;

// The flights of a placement of several UAVs by a policy for any scenario, and the steps they may
// take together, chosen on tune-many (docs/any-scenario.md, Several flights). One flight
// from the baseline leaves UAVs that started together moving together, or one stopped before a
// dip; flights from other starts find what it misses, within a cost of a few hundred steps.
constexpr int kGeneralPlacementFlights = 8;
constexpr int kGeneralPlacementStepBudget = 200;

// Where a policy for any scenario places its UAVs (`position`, a campaign's named policy): one
// UAV at the best step of its flight from the baseline (FlyGreedyToBest); several at the best of
// FlyGreedyFromStarts' flights, kGeneralPlacementFlights and kGeneralPlacementStepBudget. Both
// with kGeneralPatienceSteps.
GreedyFlight FlyGeneralPlacement(Env& env, Agent& agent, std::uint64_t seed,
                                 const EpisodeOptions& options);

}  // namespace rlpos
