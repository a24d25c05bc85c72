#pragma once
// The scenario's "env": how the agent moves the UAVs, what it observes and what it is rewarded
// for ("env.reward"), declared once (env_settings.cc) for the parser, ToJson and the docs.
#include <string>
#include <vector>

#include "common/config/setting.h"

namespace rlpos {

struct RewardSpec {
  std::string name = "paper";
  double w1 = 0.8;
  double w2 = 0.2;
  double w3 = 0.0;
};

struct EnvSpec {
  std::string fidelity = "packet";
  double step = 5.0;
  std::vector<std::string> actions = {"up", "down", "forward", "backward", "left", "right", "stay"};
  std::vector<std::string> observations = {"x", "y", "z", "n_los"};
  int observed_ues = 16;
  int height_map = 9;
  int coverage_map = 8;
  int coverage_refine = 0;
  double decision_interval = 0.1;
  double episode_duration = 100.0;
  bool action_mask = true;
  std::string action_space = "discrete";
  int turn_steps = 1;
  RewardSpec reward;  // its own table: RewardSettings()
};

// Whether `env` observes a field that means the same in every scenario (names.h).
bool UsesGeneralObservations(const EnvSpec& env);

const SettingsTable<EnvSpec>& EnvSettings();
const SettingsTable<RewardSpec>& RewardSettings();

}  // namespace rlpos
