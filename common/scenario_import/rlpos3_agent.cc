// Agent: RLpos-3's DQN (TF-Agents) hyperparameters onto ours (common/scenario/dqn_hyperparameters.h
// and agent_hyperparameters.h); the rest is how RLpos-3 runs and logs, with no equivalent here.
#include <climits>
#include <sstream>

#include "common/config/config_error.h"
#include "common/scenario/number_text.h"
#include "common/scenario_import/rlpos3_parts.h"

namespace rlpos {
namespace {

using nlohmann::json;

// "64,32" -> {64, 32}.
std::vector<int> ReadLayers(Rlpos3Object& hyper) {
  const json* v = hyper.Optional("fullyConnectedLayer");
  const std::string path = hyper.PathOf("fullyConnectedLayer");
  if (!v)
    return {};
  if (!v->is_string())
    throw ConfigError(path, "expected a string of layer sizes such as \"64,32\"");
  std::vector<int> layers;
  std::istringstream in(v->get<std::string>());
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto first = item.find_first_not_of(' ');
    const auto last = item.find_last_not_of(' ');
    const std::string digits =
        first == std::string::npos ? "" : item.substr(first, last - first + 1);
    if (digits.empty() || digits.size() > 4 ||
        digits.find_first_not_of("0123456789") != std::string::npos || std::stoi(digits) < 1) {
      throw ConfigError(path,
                        "expected layer sizes such as \"64,32\" (1 to 4096 units each), "
                        "got " +
                            v->dump());
    }
    layers.push_back(std::stoi(digits));
  }
  if (layers.empty())
    throw ConfigError(path, "expected at least one layer size, got " + v->dump());
  return layers;
}

// TF-Agents' epsilon: a polynomial decay from 1 to finalValue over decaySteps while training.
void ReadEpsilon(Rlpos3Object& hyper, DqnSpec& a) {
  Rlpos3Object epsilon = hyper.OptionalObject("epsilon");
  a.epsilon_start = 1.0;
  a.epsilon_decay_steps =
      static_cast<int>(epsilon.Integer("decaySteps", a.epsilon_decay_steps, 0, INT_MAX));
  a.epsilon_end = epsilon.Number("finalValue", a.epsilon_end);
  if (epsilon.Number("evalValue", 0.0) != 0.0) {
    epsilon.Warn("evalValue", "not carried: rlpos-sim evaluates the greedy policy (epsilon 0)");
  }
  epsilon.Finish();
}

void ReadHyperParameters(Rlpos3Object& hyper, AgentSpec& a) {
  const std::vector<int> layers = ReadLayers(hyper);
  if (!layers.empty())
    a.hidden = layers;
  a.eval_episodes = static_cast<int>(hyper.Integer("numEvalEpisodes", a.eval_episodes, 0, INT_MAX));
  if (hyper.Has("numTrainEpisodes")) {
    // RLpos-3's episodes: the whole episode, from the start position, no checkpoints.
    a.train_episodes = static_cast<int>(hyper.Integer("numTrainEpisodes", 0, 0, INT_MAX));
    a.train_episode_steps = 0;
    a.exploring_starts = false;
    a.eval_interval = 0;
  }
  DqnSpec& dqn = a.dqn;
  dqn.replay_capacity = hyper.Integer("replayBufferMaxLength", dqn.replay_capacity, 0, LLONG_MAX);
  dqn.batch_size = static_cast<int>(hyper.Integer("batchSize", dqn.batch_size, 0, INT_MAX));
  dqn.learning_rate = hyper.Number("learningRate", dqn.learning_rate);
  dqn.gamma = hyper.Number("discount", dqn.gamma);
  ReadEpsilon(hyper, dqn);
  hyper.Finish();
}

}  // namespace

void ReadAgent(Rlpos3Object& agent, Scenario& s) {
  s.agent.algorithm = "dqn";  // RLpos-3's agent is TF-Agents' DqnAgent
  Rlpos3Object hyper = agent.OptionalObject("hyperParameters");
  ReadHyperParameters(hyper, s.agent);
  agent.NotCarried("simType", "train or evaluate is the command here (rlpos-sim train, eval)");
  agent.NotCarried("newPolicy", "rlpos-sim train always starts a new policy in its --out folder");
  agent.NotCarried("dir", "rlpos-sim train --out names the folder");
  agent.NotCarried("logSteps", "rlpos-sim train writes its learning curve and trajectory anyway");
  agent.NotCarried("actionDebug", "no equivalent here");
  agent.NotCarried("debugLevel", "the agent's Python log level; here log_level");
  agent.Finish();
}

}  // namespace rlpos
