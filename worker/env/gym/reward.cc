#include "worker/env/gym/reward.h"

#include <map>
#include <stdexcept>

namespace rlpos {
namespace {

// The paper's r = w1 * nLoS / N + w2 * throughput / sum(demand).
class PaperReward : public Reward {
 public:
  explicit PaperReward(const RewardSpec& s) : w1_(s.w1), w2_(s.w2) {}
  double operator()(const RewardInput& in) const override {
    const double los = in.n_ues > 0 ? static_cast<double>(in.n_los) / in.n_ues : 0.0;
    const double thr = in.total_demand_mbps > 0 ? in.throughput_mbps / in.total_demand_mbps : 0.0;
    return w1_ * los + w2_ * thr;
  }

 private:
  double w1_, w2_;
};

// The paper's reward plus w3 * (UEs whose SNR meets their demand's MCS) / N: rewards positions
// that can carry each UE's demand, not only the ones that see it.
class DemandAwareReward : public Reward {
 public:
  explicit DemandAwareReward(const RewardSpec& s) : paper_(s), w3_(s.w3) {}
  double operator()(const RewardInput& in) const override {
    const double met = in.n_ues > 0 ? static_cast<double>(in.demands_met) / in.n_ues : 0.0;
    return paper_(in) + w3_ * met;
  }

 private:
  PaperReward paper_;
  double w3_;
};

std::map<std::string, RewardFactory>& Registry() {
  static std::map<std::string, RewardFactory> registry = {
      {"paper", [](const RewardSpec& s) { return std::make_unique<PaperReward>(s); }},
      {"demand_aware", [](const RewardSpec& s) { return std::make_unique<DemandAwareReward>(s); }},
  };
  return registry;
}

}  // namespace

RewardInput RewardInputOf(const Scenario& s, int n_los, double throughput_mbps, int demands_met) {
  return {n_los, static_cast<int>(s.ues.size()), throughput_mbps, s.TotalDemandMbps(), demands_met};
}

void RegisterReward(const std::string& name, RewardFactory factory) {
  Registry()[name] = std::move(factory);
}

std::vector<std::string> RewardNames() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : Registry())
    names.push_back(name);
  return names;
}

std::unique_ptr<Reward> MakeReward(const RewardSpec& spec) {
  const auto it = Registry().find(spec.name);
  if (it == Registry().end())
    throw std::invalid_argument("unknown reward \"" + spec.name + "\"");
  return it->second(spec);
}

}  // namespace rlpos
