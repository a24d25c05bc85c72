#pragma once
// The rewards, chosen by name from the scenario's env.reward. The names are declared once, in
// kRewards (common/scenario/names.h), which the scenario's parser accepts; a new reward is one
// class, its name there and its factory in reward.cc, in the same order.
#include <memory>

#include "common/scenario/scenario.h"

namespace rlpos {

struct RewardInput {
  int n_los = 0;
  int n_ues = 0;
  double throughput_mbps = 0.0;
  double total_demand_mbps = 0.0;
  int demands_met = 0;
};

class Reward {
 public:
  virtual ~Reward() = default;
  virtual double operator()(const RewardInput& in) const = 0;
};

// The reward's input for a UAV state in `scenario` (N and the total demand come from it).
RewardInput RewardInputOf(const Scenario& scenario, int n_los, double throughput_mbps,
                          int demands_met);

// The reward spec.name names (one of kRewards). Throws std::invalid_argument for another name.
std::unique_ptr<Reward> MakeReward(const RewardSpec& spec);

}  // namespace rlpos
