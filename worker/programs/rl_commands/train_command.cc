#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include "common/config/config_error.h"
#include "common/scenario/number_text.h"
#include "common/scenario/placement_json.h"
#include "common/scenario/scenario_parser.h"
#include "worker/env/uav_env/uav_positioning_env.h"
#include "worker/learning/agent/make_agent.h"
#include "worker/learning/agent/ppo_agent.h"
#include "worker/learning/agent_base/trainer.h"
#include "worker/learning/policy_folder/policy_folder.h"
#include "worker/learning/training/ppo_batched_training.h"
#include "worker/programs/rl_commands/generalist_train_command.h"
#include "worker/programs/rl_commands/rl_commands.h"

namespace rlpos::sim {
namespace {

namespace fs = std::filesystem;

// Episodes of train seed N run RngRun N*1000000+1, N*1000000+2, ...: never the evaluation
// runs, and never another seed's episodes (agent.train_episodes is at most 1000000).
std::uint64_t FirstEpisodeRun(std::uint64_t seed) {
  return seed * 1000000 + 1;
}

nlohmann::json ResultJson(const Scenario& s, const TrainResult& r, std::uint64_t seed) {
  const Vec3& p = r.final_info.positions.front();
  const std::uint64_t first_run = FirstEpisodeRun(seed);
  nlohmann::json result = {{"scenario", s.name},
                           {"algorithm", s.agent.algorithm},
                           {"action_space", s.env.action_space},
                           {"fidelity", s.env.fidelity},
                           {"seed", seed},
                           {"train_episodes", s.agent.train_episodes},
                           {"train_episode_steps", s.agent.train_episode_steps},
                           {"exploring_starts", s.agent.exploring_starts},
                           {"eval_episodes", s.agent.eval_episodes},
                           {"eval_interval", s.agent.eval_interval},
                           {"early_stop_checkpoints", s.agent.early_stop_checkpoints},
                           {"episodes_trained", r.episodes_trained},
                           {"policy_episode", r.policy_episode},  // the kept policy's
                           {"position", {p.x, p.y, p.z}},         // the first UAV's
                           {"positions", PlacementJson(r.final_info.positions)},  // every UAV's
                           {"n_los", r.final_info.n_los},
                           {"n_ues", s.ues.size()},
                           {"throughput_mbps", r.final_info.throughput_mbps},
                           {"demands_met", r.final_info.demands_met},
                           {"reward", r.final_reward}};
  // What a replay needs besides scenario.json: the runs, so that it flies the final evaluation.
  result.update(
      SeedStreamJson(first_run, EvaluationSeed(s.agent, first_run, s.agent.eval_episodes - 1)));
  return result;
}

const char* Phase(const EpisodeRecord& r) {
  return r.checkpoint ? "checkpoint" : r.evaluation ? "eval" : "train";
}

// x, y, z: the first UAV's final position.
void WriteCurveRow(std::ostream& out, const EpisodeRecord& r) {
  const Vec3& p = r.final_info.positions.front();
  out << r.episode << ',' << Phase(r) << ',' << r.steps << ',' << r.total_reward << ','
      << r.total_reward / std::max(1, r.steps) << ',' << r.epsilon << ',' << r.updates << ','
      << r.mean_loss << ',' << r.final_reward << ',' << p.x << ',' << p.y << ',' << p.z << ','
      << r.final_info.n_los << ',' << r.final_info.throughput_mbps << '\n';
}

// The scenario overrides the train flags make.
std::vector<std::string> TrainOverrides(const TrainOptions& t) {
  std::vector<std::string> extra;
  if (t.algorithm) {
    // SAC acts on displacements, DQN and PPO on the moves: the flag picks the space as well.
    for (auto& o : AlgorithmOverrides(*t.algorithm))
      extra.push_back(std::move(o));
  }
  if (t.fidelity)
    extra.push_back("env.fidelity=" + *t.fidelity);
  if (t.seed)
    extra.push_back("agent.seed=" + std::to_string(*t.seed));
  if (t.episodes)
    extra.push_back("agent.train_episodes=" + std::to_string(*t.episodes));
  return extra;
}

// The output is written under a temporary name (returned) and renamed at the end: no
// half-written output folder.
fs::path CreatePartialFolder(const std::string& out) {
  if (fs::exists(out)) {
    throw ConfigError("--out", out + " already exists; choose another folder or remove it");
  }
  const fs::path partial = out + ".partial";
  std::error_code ec;
  fs::remove_all(partial, ec);
  if (!fs::create_directories(partial, ec) || ec) {
    throw ConfigError("--out", "cannot create " + partial.string() + ": " + ec.message());
  }
  return partial;
}

std::ofstream OpenLearningCurve(const fs::path& file) {
  std::ofstream curve(file);
  curve << "episode,phase,steps,total_reward,mean_reward,epsilon,updates,mean_loss,final_reward,"
           "x,y,z,n_los,throughput_mbps\n";
  return curve;
}

// A training's progress on stderr (stdout holds only its result). Every episode's figures are in
// the learning curve, so a line only for the first training episode, every n-th (about
// kLines in all), the last and their checkpoints, and for each evaluation episode; and, between
// them, once kQuietAtMost has passed since the last (slow packet-level episodes still show).
// The latest line is what `status` shows of a running train job.
class ProgressLines {
 public:
  ProgressLines(const AgentSpec& spec, const Agent& agent)
      : agent_(agent),
        train_episodes_(spec.train_episodes),
        total_(spec.train_episodes + spec.eval_episodes),
        every_(std::max(1, (spec.train_episodes + kLines - 1) / kLines)) {}

  void operator()(const EpisodeRecord& r) {
    const bool evaluation = r.evaluation && !r.checkpoint;
    const bool due =
        evaluation || r.episode == 1 || r.episode % every_ == 0 || r.episode == train_episodes_;
    const auto now = Clock::now();
    if (!due && now - last_ < kQuietAtMost)
      return;
    last_ = now;
    std::string line = "episode " + std::to_string(r.episode) + "/" + std::to_string(total_) +
                       " (" + Phase(r) + "): " + std::to_string(r.steps) + " steps, reward " +
                       Number("%.1f", r.total_reward) + " (mean " +
                       Number("%.3f", r.total_reward / std::max(1, r.steps)) + ")";
    if (!r.evaluation) {  // what learnt: greedy episodes learn nothing
      if (r.updates > 0) {
        line += ", " + std::to_string(r.updates) + (r.updates == 1 ? " update" : " updates") +
                ", loss " + Number("%.4g", r.mean_loss);
      }
      const std::string own = agent_.ProgressText();  // the algorithm's own quantities
      if (!own.empty())
        line += ", " + own;
    }
    line += ", final " + DescribePlacement(r.final_info.positions) + " in LoS " +
            std::to_string(r.final_info.n_los);
    std::fprintf(stderr, "%s\n", line.c_str());
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr int kLines = 20;
  static constexpr std::chrono::seconds kQuietAtMost{30};

  static std::string Number(const char* format, double x) {
    char text[48];
    std::snprintf(text, sizeof text, format, x);
    return text;
  }

  const Agent& agent_;
  int train_episodes_, total_, every_;
  Clock::time_point last_ = Clock::now();
};

// The evaluation episodes' steps, one row each: the UAV that moved (its index), its action and
// where it went. With agent.joint_steps every UAV moves in each step: a row per UAV, its action
// the displacement it made.
class TrajectoryWriter {
 public:
  TrajectoryWriter(const fs::path& file, const Scenario& s, const Agent& agent)
      : out_(file),
        s_(s),
        agent_(agent),
        episode_(s.agent.train_episodes),
        last_(s.InitialPlacement()),
        n_uavs_(last_.size()) {
    out_ << "episode,step,uav,action,x,y,z,n_los,throughput_mbps,reward\n";
  }

  void operator()(int step, int action, const StepResult& r) {
    if (step == 1) {
      ++episode_;
      last_ = s_.InitialPlacement();
    }
    if (s_.agent.joint_steps && n_uavs_ > 1) {  // every UAV moved: a row each
      for (std::size_t u = 0; u < n_uavs_; ++u)
        Row(step, u, Displacement(u, r), r);
      last_ = r.info.positions;
      return;
    }
    // Several UAVs move in turns of env.turn_steps steps.
    const std::size_t uav = static_cast<std::size_t>((step - 1) / s_.env.turn_steps) % n_uavs_;
    // A continuous action is written as the displacement the UAV made, "dx dy dz".
    const std::string moved = agent_.Continuous()
                                  ? Displacement(uav, r)
                                  : s_.env.actions[static_cast<std::size_t>(action)];
    Row(step, uav, moved, r);
    last_ = r.info.positions;
  }
  void Close() { out_.close(); }

 private:
  std::string Displacement(std::size_t uav, const StepResult& r) const {
    const Vec3& p = r.info.positions[uav];
    const Vec3& from = last_[uav];
    return FormatNumber(p.x - from.x) + ' ' + FormatNumber(p.y - from.y) + ' ' +
           FormatNumber(p.z - from.z);
  }
  void Row(int step, std::size_t uav, const std::string& moved, const StepResult& r) {
    const Vec3& p = r.info.positions[uav];
    out_ << episode_ << ',' << step << ',' << uav << ',' << moved << ',' << p.x << ',' << p.y << ','
         << p.z << ',' << r.info.n_los << ',' << r.info.throughput_mbps << ',' << r.reward << '\n';
  }

 private:
  std::ofstream out_;
  const Scenario& s_;
  const Agent& agent_;
  int episode_;  // the evaluation episodes follow the training ones
  Placement last_;
  std::size_t n_uavs_;
};

// The steps of one training episode: agent.train_episode_steps, or the env's whole episode.
std::int64_t TrainingEpisodeSteps(const Scenario& s, const UavPositioningEnv& env) {
  const int limit = s.agent.train_episode_steps;
  return limit > 0 ? std::min(limit, env.StepsPerEpisode()) : env.StepsPerEpisode();
}

// Trains the scenario's agent, and writes into `folder` its policy, the learning curve and the
// evaluation trajectory.
TrainResult TrainAndRecord(const Scenario& s, const fs::path& folder) {
  UavPositioningEnv env(s);
  const std::unique_ptr<Agent> agent_owner =
      MakeAgent(s.agent, env, std::int64_t{s.agent.train_episodes} * TrainingEpisodeSteps(s, env));
  Agent& agent = *agent_owner;
  std::ofstream curve = OpenLearningCurve(folder / "learning_curve.csv");
  TrajectoryWriter trajectory(folder / "trajectory.csv", s, agent);
  ProgressLines progress(s.agent, agent);
  const EpisodeCallback on_episode = [&](const EpisodeRecord& r) {
    WriteCurveRow(curve, r);
    progress(r);
  };
  // PPO's rollouts from agent.ppo.num_envs analytic envs at once; the packet level is one
  // network per process, so it collects from one env.
  auto* ppo = dynamic_cast<PpoAgent*>(&agent);
  const TrainResult result = ppo && s.agent.ppo.num_envs > 1 && s.env.fidelity == "analytic"
                                 ? TrainPpoBatched(s, *ppo, FirstEpisodeRun(s.agent.seed), 0,
                                                   on_episode, std::ref(trajectory))
                                 : Train(env, agent, s.agent, FirstEpisodeRun(s.agent.seed),
                                         on_episode, std::ref(trajectory));
  curve.close();
  trajectory.Close();
  agent.Save(folder.string());
  return result;
}

void PrintTrained(const Scenario& s, const TrainResult& result, const std::string& out) {
  std::printf(
      "trained %s (%s, %s, seed %llu): final position %s, in LoS %d/%zu, reward %.4f\n"
      "policy, learning curve and result in %s\n",
      s.name.c_str(), s.agent.algorithm.c_str(), s.env.fidelity.c_str(),
      static_cast<unsigned long long>(s.agent.seed),
      DescribePlacement(result.final_info.positions).c_str(), result.final_info.n_los, s.ues.size(),
      result.final_reward, out.c_str());
}

}  // namespace

int TrainCommand(const CommonOptions& options, const TrainOptions& t) {
  if (TrainsAcrossScenarios(t))
    return GeneralistTrainCommand(options, t);
  if (options.scenario_file.empty())
    throw ConfigError("--scenario",
                      "is required (or --generated or --scenarios, for any scenario)");
  if (t.steps)
    throw ConfigError("--steps", "is for --generated and --scenarios; give --episodes");
  const Scenario s = LoadScenarioFor(options, TrainOverrides(t));
  if (s.agent.improvement_reward) {
    throw ConfigError("/agent/improvement_reward",
                      "is learnt only in training across scenarios (--generated or --scenarios)");
  }
  const fs::path partial = CreatePartialFolder(t.out);
  try {
    const TrainResult result = TrainAndRecord(s, partial);
    const nlohmann::json summary = ResultJson(s, result, s.agent.seed);
    std::ofstream(partial / "result.json") << summary.dump(2) << '\n';
    std::ofstream(partial / "scenario.json") << ToJson(s).dump(2) << '\n';
    fs::rename(partial, t.out);
    if (t.json)
      std::cout << summary.dump(2) << std::endl;
    else
      PrintTrained(s, result, t.out);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw;
  }
  return kExitOk;
}

}  // namespace rlpos::sim
