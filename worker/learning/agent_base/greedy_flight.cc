#include "worker/learning/agent_base/greedy_flight.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace rlpos {
namespace {

struct Moment {
  StepInfo info;
  double reward = 0.0;
};

GreedyFlight WholeEpisode(Env& env, Agent& agent, std::uint64_t seed,
                          const EpisodeOptions& options) {
  const EpisodeRecord record = RunEpisode(env, agent, seed, false, nullptr, options);
  return {record.final_info, record.final_reward, record.steps, record.steps};
}

// One greedy step of every agent at once (RunEpisode's joint step).
StepResult JointStep(Env& env, Agent& agent, const BoxSpace& space, const BoxSpace& box) {
  std::vector<std::vector<float>> observations;
  std::vector<ActionMask> masks;
  for (const std::vector<double>& o : env.AgentObservations())
    observations.push_back(space.Normalise(o));
  JointStepResult joint;
  if (agent.Continuous()) {
    std::vector<std::vector<double>> displacements;
    for (const std::vector<float>& o : observations)
      displacements.push_back(ScaleToBox(agent.ActContinuous(o, false), box));
    joint = env.JointStepContinuous(displacements);
  } else {
    for (std::size_t a = 0; a < observations.size(); ++a)
      masks.push_back(env.ValidActionsOf(a));
    joint = env.JointStep(agent.ActEach(observations, masks, false));
  }
  StepResult step;
  step.reward = joint.reward;
  step.terminated = joint.terminated;
  step.truncated = joint.truncated;
  step.info = std::move(joint.info);
  return step;
}

// One greedy step from `obs` (the first agent's, normalised): its own, or every agent's at once.
StepResult GreedyStep(Env& env, Agent& agent, bool joint, const BoxSpace& space,
                      const BoxSpace& box, const std::vector<float>& obs) {
  if (joint)
    return JointStep(env, agent, space, box);
  if (agent.Continuous())
    return env.StepContinuous(ScaleToBox(agent.ActContinuous(obs, false), box));
  return env.Step(agent.Act(obs, env.ValidActions(), false));
}

}  // namespace

GreedyFlight FlyGreedy(Env& env, Agent& agent, std::uint64_t seed, const EpisodeOptions& options) {
  const bool joint = options.joint && env.AgentCount() > 1;
  const BoxSpace space = env.ObservationSpace();
  const BoxSpace box = env.ContinuousActionSpace();
  std::vector<float> obs = space.Normalise(env.Reset(seed, options.reset));
  std::optional<DeterminingState> state = env.Determining();
  if (!state)
    return WholeEpisode(env, agent, seed, options);
  int steps = state->steps_left;
  if (options.max_steps > 0)
    steps = std::min(steps, options.max_steps);
  // Each state met, with the step after which it stood; moments[t] is step t + 1's outcome.
  std::map<std::vector<std::uint64_t>, int> met;
  std::vector<Moment> moments;
  met.emplace(std::move(state->key), 0);
  for (int t = 1;; ++t) {
    StepResult step = GreedyStep(env, agent, joint, space, box, obs);
    if (t >= steps || step.terminated || step.truncated)
      return {step.info, step.reward, t, t};
    moments.push_back({std::move(step.info), step.reward});
    state = env.Determining();
    if (!state)  // Env's contract: told after a Reset, told after each step of that episode
      throw std::logic_error("the env told its state after the reset but not after step " +
                             std::to_string(t));
    const auto [seen, first] = met.emplace(std::move(state->key), t);
    if (!first) {
      // The states after step s = seen->second repeat with period t - s: the last step's is
      // the one (steps - s) mod period steps after s.
      const int s = seen->second;
      const int period = t - s;
      const int last = s + (steps - s) % period;
      const Moment& end = moments[static_cast<std::size_t>((last == s ? s + period : last) - 1)];
      return {end.info, end.reward, steps, t};
    }
    if (!joint)  // the agents' observations are read from the env at each joint step
      obs = space.Normalise(step.observation);
  }
}

GreedyFlight FlyGreedyToBest(Env& env, Agent& agent, std::uint64_t seed,
                             const EpisodeOptions& options, int patience_steps) {
  const bool joint = options.joint && env.AgentCount() > 1;
  const BoxSpace space = env.ObservationSpace();
  const BoxSpace box = env.ContinuousActionSpace();
  std::vector<float> obs = space.Normalise(env.Reset(seed, options.reset));
  std::optional<DeterminingState> state = env.Determining();
  std::set<std::vector<std::uint64_t>> met;
  if (state)
    met.insert(std::move(state->key));
  GreedyFlight best;
  best.final_reward = -std::numeric_limits<double>::infinity();
  for (int t = 1;; ++t) {
    StepResult step = GreedyStep(env, agent, joint, space, box, obs);
    if (t == 1 || step.reward > best.final_reward) {
      best.final_reward = step.reward;
      best.final_info = step.info;
      best.best_step = t;
    }
    best.steps = best.steps_flown = t;
    const bool patience_out = patience_steps > 0 && t - best.best_step >= patience_steps;
    const bool limit = options.max_steps > 0 && t >= options.max_steps;
    if (patience_out || limit || step.terminated || step.truncated)
      return best;
    if (state) {
      state = env.Determining();
      if (!state)
        throw std::logic_error("the env told its state after the reset but not after step " +
                               std::to_string(t));
      if (!met.insert(std::move(state->key)).second)
        return best;
    }
    if (!joint)
      obs = space.Normalise(step.observation);
  }
}

GreedyFlight FlyGreedyFromStarts(Env& env, Agent& agent, std::uint64_t seed,
                                 const EpisodeOptions& options, int patience_steps, int flights,
                                 int step_budget) {
  if (flights < 1)
    throw std::invalid_argument("a placement needs at least one flight, not " +
                                std::to_string(flights));
  GreedyFlight best = FlyGreedyToBest(env, agent, seed, options, patience_steps);
  int steps = best.steps;
  for (int k = 1; k < flights && steps < step_budget; ++k) {
    EpisodeOptions drawn = options;
    drawn.reset.random_start = true;
    const int left = step_budget - steps;
    drawn.max_steps = options.max_steps > 0 ? std::min(options.max_steps, left) : left;
    const GreedyFlight flight =
        FlyGreedyToBest(env, agent, seed + static_cast<std::uint64_t>(k), drawn, patience_steps);
    steps += flight.steps;
    if (flight.final_reward > best.final_reward)
      best = flight;
  }
  best.steps = best.steps_flown = steps;
  return best;
}

GreedyFlight FlyGeneralPlacement(Env& env, Agent& agent, std::uint64_t seed,
                                 const EpisodeOptions& options) {
  if (env.AgentCount() < 2)
    return FlyGreedyToBest(env, agent, seed, options, kGeneralPatienceSteps);
  return FlyGreedyFromStarts(env, agent, seed, options, kGeneralPatienceSteps,
                             kGeneralPlacementFlights, kGeneralPlacementStepBudget);
}

}  // namespace rlpos
