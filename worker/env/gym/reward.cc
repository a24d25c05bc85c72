#include "worker/env/gym/reward.h"

#include <array>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "common/scenario/names.h"

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

using RewardFactory = std::unique_ptr<Reward> (*)(const RewardSpec&);

template <typename R>
std::unique_ptr<Reward> Make(const RewardSpec& spec) {
  return std::make_unique<R>(spec);
}

// One factory per name of kRewards, in its order: the parser accepts exactly these.
constexpr std::array<std::pair<std::string_view, RewardFactory>, 2> kFactories{{
    {"paper", Make<PaperReward>},
    {"demand_aware", Make<DemandAwareReward>},
}};

constexpr bool NamesMatch() {
  if (kFactories.size() != kRewards.size())
    return false;
  for (std::size_t i = 0; i < kRewards.size(); ++i) {
    if (kFactories[i].first != kRewards[i])
      return false;
  }
  return true;
}
static_assert(NamesMatch(), "kFactories must name the rewards of kRewards, in its order");

}  // namespace

RewardInput RewardInputOf(const Scenario& s, int n_los, double throughput_mbps, int demands_met) {
  return {n_los, static_cast<int>(s.ues.size()), throughput_mbps, s.TotalDemandMbps(), demands_met};
}

std::unique_ptr<Reward> MakeReward(const RewardSpec& spec) {
  for (const auto& [name, factory] : kFactories) {
    if (name == spec.name)
      return factory(spec);
  }
  throw std::invalid_argument("unknown reward \"" + spec.name + "\"");
}

}  // namespace rlpos
