#pragma once
// The scenario's "agent": its algorithm and networks, declared once (agent_settings.cc), and each
// algorithm's hyperparameters in their own tables (*_hyperparameters.h).
#include <string>
#include <vector>

#include "common/config/setting.h"
#include "common/scenario/agent_hyperparameters.h"
#include "common/scenario/dqn_hyperparameters.h"
#include "common/scenario/ppo_hyperparameters.h"
#include "common/scenario/sac_hyperparameters.h"

namespace rlpos {

// The agent: its algorithm, network and hyperparameters. Each algorithm declares its own in
// one file (scenario/dqn_hyperparameters.h, ppo_..., sac_...) and reads only its own member;
// the keys every algorithm shares (agent_hyperparameters.h) are the base, as their keys sit in
// "agent" itself. DQN's keys sit in "agent" too (DQN came first), but in C++ they are
// agent.dqn: a PPO or SAC that named DQN's gamma or replay would not compile.
// agent.ue_encoder's bounds: a few small layers, applied to each UE slot.
constexpr int kMaxUeEncoderLayers = 4;
constexpr int kMaxUeEncoderWidth = 512;

struct AgentSpec : AgentCommonSpec {
  std::string algorithm = "dqn";
  std::vector<int> hidden = {32, 32};
  // PPO only, with "ues" in env.observations: the widths of a network shared by the UE slots
  // (ReLU after each), whose mean over the present slots stands in for the slots in the input of
  // the hidden layers, so the policy takes the UEs as a set. Empty: none, the slots go in as they
  // are.
  std::vector<int> ue_encoder;
  DqnSpec dqn;
  PpoSpec ppo;
  SacSpec sac;
};

// agent.algorithm, agent.hidden and agent.ue_encoder.
const SettingsTable<AgentSpec>& AgentNetworkSettings();

}  // namespace rlpos
