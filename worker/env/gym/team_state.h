#pragma once
// What a centralised critic sees beside a UAV's own observation when the UAVs move at once
// (agent.ppo.centralised_critic): the team's standing and every UAV's share of it, in slots of
// fixed count, so that its layout is the same in every scenario (MAPPO's agent-specific global
// state: the agent's own view plus what only the whole team knows). kTeamStateWidth values, each
// in [0, 1]:
//   the shares of the UEs in LoS of their UAV and of those whose demand is met, the throughput
//   over the total demand (clipped), and the UAV count over 1 + kOtherUavSlots;
//   then 1 + kOtherUavSlots slots of [present, served, served in LoS] (the shares of all UEs
//   the UAV serves, and serves in LoS): the UAV itself first, then the others in the order of
//   "others" (nearest first), then empty slots of zeros.
#include <cstddef>
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/general_observation.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

constexpr int kTeamUavSlots = 1 + kOtherUavSlots;
constexpr int kTeamUavSlotWidth = 3;
constexpr int kTeamStateWidth = 4 + kTeamUavSlots * kTeamUavSlotWidth;

BoxSpace TeamStateBounds();
// UAV `uav`'s team state at the moment `info` describes. std::logic_error for an info that does
// not match the scenario's UAVs and UEs.
std::vector<double> TeamState(const Scenario& scenario, const StepInfo& info, std::size_t uav);

}  // namespace rlpos
