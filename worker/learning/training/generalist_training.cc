#include "worker/learning/training/generalist_training.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/env/vector_env/thread_pool.h"
#include "worker/learning/agent_base/greedy_flight.h"
#include "worker/learning/agent_base/trainer.h"
#include "worker/positioning/positioners/positioners.h"

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

// One env of a round: its episode's scenario and where the episode stands. Its agents: the UAV
// whose turn it is (one row), or with agent.joint_steps every UAV (a row each, moving at once).
struct Lane {
  std::unique_ptr<UavPositioningEnv> env;
  bool joint = false;
  std::vector<std::vector<float>> observations;  // normalised, one per agent
  std::vector<ActionMask> masks;
  std::vector<std::vector<float>> team_states;  // with a centralised critic
  double reward = 0.0;                          // of the last step
  double best = 0.0;                            // the episode's best reward so far
  bool terminated = false;
  bool truncated = false;
  bool running = false;
  int steps = 0;
};

class Round {
 public:
  Round(const ScenarioDraw& draw, const AgentSpec& spec, const BoxSpace& space, ThreadPool& pool,
        bool teams)
      : draw_(draw), spec_(spec), space_(space), pool_(pool), teams_(teams) {}

  // Env i flies training episode first + i (its draw and run), for i < lanes.
  void Start(std::int64_t first, std::size_t lanes, std::uint64_t episode_run) {
    lanes_.resize(lanes);
    pool_.ForEach(lanes, [&](std::size_t i) {
      const auto episode = static_cast<std::uint64_t>(first) + i;
      Lane& lane = lanes_[i];
      lane.env = std::make_unique<UavPositioningEnv>(draw_.Training(episode).scenario);
      if (lane.env->ObservationSpace().Dim() != space_.Dim())
        throw std::logic_error("a drawn scenario's observation differs from the policy's");
      lane.joint = spec_.joint_steps && lane.env->AgentCount() > 1;
      const EpisodeOptions options = TrainingEpisodeOptions(spec_, static_cast<int>(episode));
      See(lane, lane.env->Reset(episode_run + episode, options.reset));
      lane.best = lane.env->RewardOf(lane.env->LastInfo());
      lane.running = true;
      lane.steps = 0;
    });
  }

  // Flies every lane to its episode's end; returns the transitions learnt from (one per agent
  // and step).
  std::int64_t Fly(PpoAgent& agent, double& final_reward_sum) {
    std::int64_t transitions_seen = 0;
    for (;;) {
      const std::vector<int> active = Running();
      if (active.empty())
        return transitions_seen;
      LaneBatch batch = TakeBatch(active);
      const std::vector<int> actions = agent.ActBatch(batch.observations, batch.masks);
      Step(active, batch.first_row, actions);
      std::vector<Transition> transitions = Learnt(active, actions, batch, final_reward_sum);
      transitions_seen += static_cast<std::int64_t>(transitions.size());
      agent.ObserveBatch(std::move(transitions), batch.streams);
    }
  }

 private:
  // The rows the agent acts on, its agents' rows for each active lane in turn (taken from the
  // lanes).
  struct LaneBatch {
    std::vector<std::size_t> first_row;  // of each active lane
    std::vector<std::vector<float>> observations;
    std::vector<ActionMask> masks;
    std::vector<std::vector<float>> team_states;
    std::vector<int> streams;
  };

  std::vector<int> Running() const {
    std::vector<int> active;
    for (std::size_t i = 0; i < lanes_.size(); ++i) {
      if (lanes_[i].running)
        active.push_back(static_cast<int>(i));
    }
    return active;
  }

  LaneBatch TakeBatch(const std::vector<int>& active) {
    LaneBatch b;
    std::size_t rows = 0;
    for (int i : active) {
      b.first_row.push_back(rows);
      rows += lanes_[static_cast<std::size_t>(i)].observations.size();
    }
    b.observations.resize(rows);
    b.masks.resize(rows);
    b.team_states.resize(rows);
    b.streams.resize(rows);
    for (std::size_t k = 0; k < active.size(); ++k) {
      Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
      for (std::size_t a = 0; a < lane.observations.size(); ++a) {
        const std::size_t r = b.first_row[k] + a;
        b.observations[r] = std::move(lane.observations[a]);
        b.masks[r] = std::move(lane.masks[a]);
        if (teams_)
          b.team_states[r] = std::move(lane.team_states[a]);
        // GAE follows each agent's own stream (with turns, the lane's one stream).
        b.streams[r] = active[k] * static_cast<int>(kMaxUavs) + static_cast<int>(a);
      }
    }
    return b;
  }

  // Every active lane takes its step, on the pool.
  void Step(const std::vector<int>& active, const std::vector<std::size_t>& first_row,
            const std::vector<int>& actions) {
    pool_.ForEach(active.size(), [&](std::size_t k) {
      Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
      if (lane.joint) {
        const auto from = actions.begin() + static_cast<long>(first_row[k]);
        const JointStepResult r =
            lane.env->JointStep(std::vector<int>(from, from + lane.env->AgentCount()));
        lane.reward = r.reward;
        lane.terminated = r.terminated;
        lane.truncated = r.truncated;
        See(lane, {});  // on the pool too: the masks probe every move, the look around evaluates
      } else {
        StepResult r = lane.env->Step(actions[first_row[k]]);
        lane.reward = r.reward;
        lane.terminated = r.terminated;
        lane.truncated = r.truncated;
        See(lane, std::move(r.observation));
      }
    });
  }

  // The step's transitions, one per agent of each active lane; ends the lanes whose episode
  // ended, adding their final reward to `final_reward_sum`.
  std::vector<Transition> Learnt(const std::vector<int>& active, const std::vector<int>& actions,
                                 LaneBatch& b, double& final_reward_sum) {
    const int limit = spec_.train_episode_steps;
    std::vector<Transition> transitions(b.observations.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
      Lane& lane = lanes_[static_cast<std::size_t>(active[k])];
      ++lane.steps;
      const double learnt = LearntReward(spec_, lane.reward, lane.best);
      const bool truncated = lane.truncated || (limit > 0 && lane.steps >= limit);
      const bool end = lane.terminated || truncated;
      for (std::size_t a = 0; a < lane.observations.size(); ++a) {
        const std::size_t r = b.first_row[k] + a;
        Transition& t = transitions[r];
        t.observation = std::move(b.observations[r]);
        t.action = actions[r];
        t.reward = static_cast<float>(learnt);
        t.next_observation = lane.observations[a];
        t.terminal = lane.terminated;
        t.next_mask = lane.masks[a];
        t.episode_end = end;
        if (teams_) {
          t.team_state = std::move(b.team_states[r]);
          t.next_team_state = lane.team_states[a];
        }
      }
      if (end) {
        lane.running = false;
        final_reward_sum += lane.reward;
        lane.env.reset();  // its scenario's memory goes now, not with the next round
      }
    }
    return transitions;
  }

  // The lane's agents' observations, masks and team states now; `turn`: the observation of the
  // UAV whose turn it is, as the env's last Reset or Step gave it (unused with joint steps).
  void See(Lane& lane, const std::vector<double>& turn) const {
    const UavPositioningEnv& env = *lane.env;
    lane.observations.clear();
    lane.masks.clear();
    lane.team_states.clear();
    if (lane.joint) {
      for (const std::vector<double>& o : env.AgentObservations())
        lane.observations.push_back(space_.Normalise(o));
      for (std::size_t a = 0; a < env.AgentCount(); ++a) {
        lane.masks.push_back(env.ValidActionsOf(a));
        if (teams_)
          lane.team_states.push_back(TeamStateFor(env, a));
      }
      return;
    }
    lane.observations.push_back(space_.Normalise(turn));
    lane.masks.push_back(env.ValidActions());
    if (teams_)
      lane.team_states.push_back(
          TeamStateFor(env, static_cast<std::size_t>(env.LastInfo().active_uav)));
  }

  const ScenarioDraw& draw_;
  const AgentSpec& spec_;
  const BoxSpace& space_;
  ThreadPool& pool_;
  bool teams_;
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
    const GreedyFlight r = FlyGreedyToBest(env, agent, kValidationRun, GreedyEpisodeOptions(spec),
                                           kGeneralPatienceSteps);
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
  Round round(draw, spec, space, pool, agent.NeedsTeamState());
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
