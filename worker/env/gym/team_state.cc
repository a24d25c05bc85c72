#include "worker/env/gym/team_state.h"

#include <algorithm>
#include <stdexcept>

namespace rlpos {
namespace {

double Share(double part, double whole) {
  return whole > 0.0 ? std::clamp(part / whole, 0.0, 1.0) : 0.0;
}

}  // namespace

BoxSpace TeamStateBounds() {
  BoxSpace box;
  box.low.assign(kTeamStateWidth, 0.0);
  box.high.assign(kTeamStateWidth, 1.0);
  return box;
}

std::vector<double> TeamState(const Scenario& scenario, const StepInfo& info, std::size_t uav) {
  const std::size_t n_ues = scenario.ues.size();
  const std::size_t n_uavs = scenario.uavs.size();
  if (info.positions.size() != n_uavs || uav >= n_uavs || info.serving.size() != n_ues ||
      info.los.size() != n_ues)
    throw std::logic_error("team state: the step's info does not match the scenario");
  double demand = 0.0;
  for (const UeSpec& ue : scenario.ues)
    demand += ue.demand_mbps;
  const auto ues = static_cast<double>(n_ues);
  std::vector<double> state;
  state.reserve(kTeamStateWidth);
  state.push_back(Share(info.n_los, ues));
  state.push_back(Share(info.demands_met, ues));
  state.push_back(Share(info.throughput_mbps, demand));
  state.push_back(Share(static_cast<double>(n_uavs), kTeamUavSlots));
  std::vector<std::size_t> order{uav};
  for (std::size_t other : OtherUavsNearestFirst(info, uav))
    order.push_back(other);
  for (std::size_t k = 0; k < static_cast<std::size_t>(kTeamUavSlots); ++k) {
    if (k >= order.size()) {
      state.insert(state.end(), kTeamUavSlotWidth, 0.0);
      continue;
    }
    int served = 0;
    int in_los = 0;
    for (std::size_t i = 0; i < n_ues; ++i) {
      if (info.serving[i] == static_cast<int>(order[k])) {
        ++served;
        in_los += info.los[i] ? 1 : 0;
      }
    }
    state.push_back(1.0);
    state.push_back(Share(served, ues));
    state.push_back(Share(in_los, ues));
  }
  return state;
}

}  // namespace rlpos
