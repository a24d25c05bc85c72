#pragma once
// Pluggable rewards, chosen by name from the scenario's env.reward (a registry, so a new reward
// is one class and one RegisterReward call).
#include <functional>
#include <memory>
#include <string>
#include <vector>

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

using RewardFactory = std::function<std::unique_ptr<Reward>(const RewardSpec&)>;

void RegisterReward(const std::string& name, RewardFactory factory);
std::vector<std::string> RewardNames();
// Throws std::invalid_argument for an unknown name.
std::unique_ptr<Reward> MakeReward(const RewardSpec& spec);

}  // namespace rlpos
