// Where each field of an imported scenario came from in the RLpos-3 config: errors found on the
// scenario (its parser, ns-3's checks) name the field the user wrote.
#include <sstream>
#include <vector>

#include "common/scenario_import/rlpos3_import.h"

namespace rlpos {
namespace {

struct PathRule {
  const char* ours;    // segments; "*" matches an index
  const char* source;  // "*" takes the matched index
  bool keep_rest;      // append what follows the match (same layout below it)
};

// Most specific first.
const std::vector<PathRule>& Rules() {
  static const std::vector<PathRule> rules = {
      {"/ues/*/position", "/ns3Sim/defaultValues/UENodes/*/positionVector", true},
      {"/ues/*/demand", "/ns3Sim/defaultValues/UENodes/*/DataRate", false},
      {"/ues/*", "/ns3Sim/defaultValues/UENodes/*", false},
      {"/ues", "/ns3Sim/defaultValues/UENodes", false},
      {"/buildings/*", "/ns3Sim/defaultValues/Buildings/*/BuildingPosition", false},
      {"/uav/position", "/ns3Sim/defaultValues/UAVNodes/0/positionVector", true},
      {"/uav/zone", "/Gym/venueSize", false},
      {"/uav", "/ns3Sim/defaultValues/UAVNodes/0", false},
      {"/uavs/*/position", "/ns3Sim/defaultValues/UAVNodes/*/positionVector", true},
      {"/uavs/*/zone", "/Gym/venueSize", false},
      {"/uavs/*", "/ns3Sim/defaultValues/UAVNodes/*", false},
      {"/uavs", "/ns3Sim/defaultValues/UAVNodes", false},
      {"/venue", "/Gym/venueSize", false},
      {"/wifi/standard", "/ns3Sim/configSim/wifiStandard", false},
      {"/wifi/channel", "/ns3Sim/defaultValues/wifiChannelNumber", false},
      {"/wifi/width", "/ns3Sim/defaultValues/channelBW", false},
      {"/wifi/guard_interval", "/ns3Sim/defaultValues/GuardInterval", false},
      {"/wifi/tx_power", "/ns3Sim/defaultValues/txpower", false},
      {"/wifi/antenna_gain", "/ns3Sim/defaultValues/antennaGain", false},
      {"/wifi/noise_floor", "/ns3Sim/defaultValues/PN", false},
      {"/wifi/rate_manager", "/ns3Sim/configSim/RemotStManager", false},
      {"/traffic/protocol", "/ns3Sim/configSim/trafficProtocol", false},
      {"/simulation/seed", "/ns3Sim/defaultValues/simSeed", false},
      {"/simulation/run", "/ns3Sim/defaultValues/simRun", false},
      {"/env/step", "/Gym/venueSize/gridResolution", false},
      {"/env/decision_interval", "/Gym/decisionInterval", false},
      {"/env/episode_duration", "/ns3Sim/defaultValues/simDuration", false},
      {"/env/actions", "/ns3Sim/configSim/UAV_directions", true},
      {"/agent/hidden", "/Agent/hyperParameters/fullyConnectedLayer", false},
      {"/agent/train_episodes", "/Agent/hyperParameters/numTrainEpisodes", false},
      {"/agent/eval_episodes", "/Agent/hyperParameters/numEvalEpisodes", false},
      {"/agent/replay_capacity", "/Agent/hyperParameters/replayBufferMaxLength", false},
      {"/agent/batch_size", "/Agent/hyperParameters/batchSize", false},
      {"/agent/learning_rate", "/Agent/hyperParameters/learningRate", false},
      {"/agent/gamma", "/Agent/hyperParameters/discount", false},
      {"/agent/epsilon_decay_steps", "/Agent/hyperParameters/epsilon/decaySteps", false},
      {"/agent/epsilon_end", "/Agent/hyperParameters/epsilon/finalValue", false},
  };
  return rules;
}

std::vector<std::string> Segments(const std::string& path) {
  std::vector<std::string> out;
  std::istringstream in(path);
  std::string part;
  while (std::getline(in, part, '/')) {
    if (!part.empty())
      out.push_back(part);
  }
  return out;
}

bool IsIndex(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

std::string Rlpos3SourcePath(const std::string& scenario_path) {
  const std::vector<std::string> path = Segments(scenario_path);
  for (const PathRule& rule : Rules()) {
    const std::vector<std::string> pattern = Segments(rule.ours);
    if (pattern.size() > path.size())
      continue;
    std::string index;
    bool match = true;
    for (std::size_t i = 0; i < pattern.size() && match; ++i) {
      if (pattern[i] == "*" && IsIndex(path[i]))
        index = path[i];
      else
        match = pattern[i] == path[i];
    }
    if (!match)
      continue;
    std::string source = rule.source;
    const auto star = source.find('*');
    if (star != std::string::npos)
      source.replace(star, 1, index);
    for (std::size_t i = pattern.size(); rule.keep_rest && i < path.size(); ++i)
      source += "/" + path[i];
    return source;
  }
  return scenario_path;
}

}  // namespace rlpos
