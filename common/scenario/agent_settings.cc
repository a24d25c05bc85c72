#include "common/scenario/agent_settings.h"

#include <cmath>

#include "common/scenario/names.h"

namespace rlpos {
namespace {

using nlohmann::json;

void ReadHidden(AgentSpec& a, const json& h, const std::string& path) {
  if (!h.is_array() || h.empty())
    throw ConfigError(path, "expected [units, ...]");
  std::vector<int> hidden;
  for (std::size_t i = 0; i < h.size(); ++i) {
    hidden.push_back(static_cast<int>(CheckedNumber(h[i], JoinPath(path, i), Between(1, 4096))));
  }
  a.hidden = hidden;
}

json HiddenJson(const AgentSpec& a) {
  return a.hidden;
}

void ReadUeEncoder(AgentSpec& a, const json& e, const std::string& path) {
  if (!e.is_array())
    throw ConfigError(path, "expected [units, ...] (or [] for none)");
  if (e.size() > static_cast<std::size_t>(kMaxUeEncoderLayers)) {
    throw ConfigError(
        path, std::to_string(e.size()) + " layers; at most " + std::to_string(kMaxUeEncoderLayers));
  }
  std::vector<int> widths;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::string at = JoinPath(path, i);
    const double units = CheckedNumber(e[i], at, Between(1, kMaxUeEncoderWidth));
    if (units != std::floor(units))
      throw ConfigError(at, "expected an integer");
    widths.push_back(static_cast<int>(units));
  }
  a.ue_encoder = widths;
}

json UeEncoderJson(const AgentSpec& a) {
  return a.ue_encoder;
}

}  // namespace

const SettingsTable<AgentSpec>& AgentNetworkSettings() {
  static const SettingsTable<AgentSpec> table{
      "agent.network",
      "/agent",
      "The agent's algorithm and networks; every other key of \"agent\" is a hyperparameter "
      "(the agent, dqn, ppo and sac tables).",
      {{"algorithm", &AgentSpec::algorithm, NoRange(),
        "sac needs env.action_space \"continuous\"; rlpos-sim train --algorithm X sets both", "",
        NameList(kAlgorithms)},
       {"hidden", CustomValue<AgentSpec>{ReadHidden, HiddenJson, "[units, ...]"}, NoRange(),
        "fully connected layers (ReLU) of every algorithm's networks, each of 1-4096 units; the "
        "paper's Table II"},
       {"ue_encoder",
        CustomValue<AgentSpec>{ReadUeEncoder, UeEncoderJson, "[units, ...]"},
        NoRange(),
        "PPO only, with \"ues\" in env.observations: the widths (at most 4 layers, each 1-512) "
        "of a network shared by the UE slots, so that the policy takes the UEs as a set; []: none",
        "",
        {},
        nullptr,
        [](const AgentSpec& a) { return !a.ue_encoder.empty(); }}}};
  return table;
}

}  // namespace rlpos
