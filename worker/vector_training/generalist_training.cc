#include "worker/vector_training/generalist_training.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "worker/agent/greedy_flight.h"
#include "worker/agent/trainer.h"
#include "worker/positioners/positioners.h"
#include "worker/uav_env/uav_positioning_env.h"
#include "worker/vector_env/thread_pool.h"

namespace rlpos {
namespace {

// The validation flights' RngRun (it shapes nothing at analytic fidelity, but is fixed).
constexpr std::uint64_t kValidationRun = 1;

double MeanRatio(const std::vector<ValidationScore>& scores) {
  double sum = 0.0;
  for (const auto& s : scores)
    sum += s.ratio;
  return scores.empty() ? 0.0 : sum / static_cast<double>(scores.size());
}

double WorstRatio(const std::vector<ValidationScore>& scores) {
  double worst = 1.0;
  for (const auto& s : scores)
    worst = std::min(worst, s.ratio);
  return worst;
}

std::size_t ThreadsFor(std::size_t asked, std::size_t work) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  return asked > 0 ? asked : std::max<std::size_t>(1, std::min(cores, work));
}

// One env of a round: its episode's scenario and where the episode stands.
struct Lane {
  std::unique_ptr<UavPositioningEnv> env;
  std::vector<float> observation;  // normalised
  ActionMask mask;
  StepResult last;
  ActionMask next_mask;  // the mask after the last step
  bool running = false;
  int steps = 0;
};

class Round {
 public:
  Round(const ScenarioDraw& draw, const AgentSpec& spec, const BoxSpace& space, ThreadPool& pool)
      : draw_(draw), spec_(spec), space_(space), pool_(pool) {}

  // Env i flies training episode first + i (its draw and run), for i < lanes.
  void Start(std::int64_t first, std::size_t lanes, std::uint64_t episode_run) {
    lanes_.resize(lanes);
    pool_.ForEach(lanes, [&](std::size_t i) {
      const auto episode = static_cast<std::uint64_t>(first) + i;
      Lane& lane = lanes_[i];
      lane.env = std::make_unique<UavPositioningEnv>(draw_.Training(episode).scenario);
      if (lane.env->ObservationSpace().Dim() != space_.Dim())
        throw std::logic_error("a drawn scenario's observation differs from the policy's");
      const EpisodeOptions options = TrainingEpisodeOptions(spec_, static_cast<int>(episode));
      lane.observation = space_.Normalise(lane.env->Reset(episode_run + episode, options.reset));
      lane.mask = lane.env->ValidActions();
      lane.running = true;
      lane.steps = 0;
    });
  }

  // Flies every lane to its episode's end; returns the transitions learnt from.
  std::int64_t Fly(PpoAgent& agent, double& final_reward_sum) {
    const int limit = spec_.train_episode_steps;
    std::int64_t transitions_seen = 0;
    std::vector<int> active;
    for (;;) {
      active.clear();
      for (std::size_t i = 0; i < lanes_.size(); ++i) {
        if (lanes_[i].running)
          active.push_back(static_cast<int>(i));
      }
      if (active.empty())
        return transitions_seen;
      std::vector<std::vector<float>> batch(active.size());
      std::vector<ActionMask> masks(active.size());
      for (std::size_t k = 0; k < active.size(); ++k) {
        Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
        batch[k] = lane.observation;
        masks[k] = lane.mask;
      }
      const std::vector<int> actions = agent.ActBatch(batch, masks);
      pool_.ForEach(active.size(), [&](std::size_t k) {
        Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
        lane.last = lane.env->Step(actions[k]);
        lane.next_mask = lane.env->ValidActions();  // on the pool too: it probes every move
      });
      std::vector<Transition> transitions(active.size());
      for (std::size_t k = 0; k < active.size(); ++k) {
        Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
        const StepResult& r = lane.last;
        ++lane.steps;
        const bool truncated = r.truncated || (limit > 0 && lane.steps >= limit);
        Transition& t = transitions[k];
        t.observation = std::move(batch[k]);
        t.action = actions[k];
        t.reward = static_cast<float>(r.reward);
        t.next_observation = space_.Normalise(r.observation);
        t.terminal = r.terminated;
        t.next_mask = std::move(lane.next_mask);
        t.episode_end = r.terminated || truncated;
        lane.observation = t.next_observation;
        lane.mask = t.next_mask;
        if (t.episode_end) {
          lane.running = false;
          final_reward_sum += r.reward;
          lane.env.reset();  // its scenario's memory goes now, not with the next round
        }
      }
      transitions_seen += static_cast<std::int64_t>(transitions.size());
      agent.ObserveBatch(std::move(transitions), active);
    }
  }

 private:
  const ScenarioDraw& draw_;
  const AgentSpec& spec_;
  const BoxSpace& space_;
  ThreadPool& pool_;
  std::vector<Lane> lanes_;
};

}  // namespace

std::vector<ValidationScenario> ValidationSet(const ScenarioDraw& draw, int count,
                                              std::size_t threads) {
  std::vector<ValidationScenario> set(static_cast<std::size_t>(count));
  ThreadPool pool(ThreadsFor(threads, set.size()));
  pool.ForEach(set.size(), [&](std::size_t i) {
    set[i].drawn = draw.Validation(i);
    OracleOptions analytic_only;
    analytic_only.packet_candidates = 0;
    set[i].oracle_reward =
        OracleSearch(set[i].drawn.scenario, analytic_only).front().analytic_reward;
  });
  return set;
}

std::vector<ValidationScore> ScoreGreedy(const std::vector<ValidationScenario>& scenarios,
                                         Agent& agent, const AgentSpec& spec) {
  std::vector<ValidationScore> scores;
  for (const ValidationScenario& v : scenarios) {
    UavPositioningEnv env(v.drawn.scenario);
    const GreedyFlight r = FlyGreedy(env, agent, kValidationRun, GreedyEpisodeOptions(spec));
    const double ratio = v.oracle_reward > 0 ? r.final_reward / v.oracle_reward : 1.0;
    scores.push_back({v.drawn.origin, r.final_reward, v.oracle_reward, ratio, r.final_info.n_los,
                      v.drawn.scenario.ues.size()});
  }
  return scores;
}

GeneralistResult TrainGeneralist(const ScenarioDraw& draw, PpoAgent& agent, const AgentSpec& spec,
                                 const GeneralistOptions& options, std::uint64_t episode_run,
                                 const GeneralistProgressCallback& on_progress,
                                 const GeneralistCheckpoints& checkpoints) {
  if (options.steps <= 0)
    throw std::invalid_argument("the training budget must be at least one step");
  const auto n = static_cast<std::size_t>(spec.ppo.num_envs);
  ThreadPool pool(ThreadsFor(options.threads, n));
  const std::vector<ValidationScenario> validation =
      ValidationSet(draw, options.validation_scenarios, options.threads);
  const BoxSpace space = UavPositioningEnv(validation.front().drawn.scenario).ObservationSpace();
  const std::int64_t every = options.validation_every > 0
                                 ? options.validation_every
                                 : std::max<std::int64_t>(1, options.steps / 10);

  GeneralistResult result;
  result.first_draw = 0;
  std::optional<double> best;
  std::int64_t next_validation = every;
  if (checkpoints.resume) {
    result = checkpoints.resume->result;
    best = checkpoints.resume->best;
    next_validation = checkpoints.resume->next_validation;
  }
  Round round(draw, spec, space, pool);
  const auto validate = [&](GeneralistProgress& progress) {
    std::vector<ValidationScore> scores = ScoreGreedy(validation, agent, spec);
    const double mean = MeanRatio(scores);
    progress.validation = mean;
    progress.validation_worst = WorstRatio(scores);
    if (!best || mean >= *best) {
      best = mean;
      agent.KeepPolicy();
      result.kept_at_steps = result.steps;
      result.validation = std::move(scores);
    }
    progress.best_validation = best;
  };
  while (result.steps < options.steps) {
    round.Start(result.episodes, n, episode_run);
    double final_reward_sum = 0.0;
    result.steps += round.Fly(agent, final_reward_sum);
    result.episodes += static_cast<std::int64_t>(n);
    GeneralistProgress progress;
    progress.steps = result.steps;
    progress.episodes = result.episodes;
    progress.train_final_reward = final_reward_sum / static_cast<double>(n);
    progress.best_validation = best;
    if (result.steps >= next_validation || result.steps >= options.steps) {
      validate(progress);
      next_validation += every;
    }
    if (on_progress)
      on_progress(progress);
    if (checkpoints.save && result.steps < options.steps && agent.AtRolloutStart() &&
        (!checkpoints.due || checkpoints.due()))
      checkpoints.save({result, best, next_validation});
  }
  result.last_draw = static_cast<std::uint64_t>(result.episodes) - 1;
  result.best_validation = *best;
  agent.RestoreKeptPolicy();
  return result;
}

}  // namespace rlpos
