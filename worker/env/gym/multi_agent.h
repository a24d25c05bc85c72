#pragma once
// Several UAVs as agents that move at once (UavPositioningEnv::JointStep, rlpos.parallel_env):
// the joint move and its conflict rule, each UAV's own observation, and the global state a
// centralised critic (MAPPO, QMIX) sees.
#include <cstddef>
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"
#include "worker/env/gym/env.h"
#include "worker/env/gym/spaces.h"

namespace rlpos {

// The placement after every UAV u takes displacements[u] at once. Each target is first
// resolved alone (TargetAlone: clamped to the UAV's zone; into a building: stays). Then, while
// some UAV that moves would end closer than kMinUavSeparation to another UAV's end point, the
// highest-indexed such UAV is refused and stays where it was (a refusal can put a UAV back in
// another's way, hence the repeat). So a lower index has priority, the result is
// deterministic, and no two UAVs end closer than kMinUavSeparation if none started so. Only the
// end points count: two UAVs may swap places, as one UAV may hop past another in Step.
// `buildings`: BuildingObstacles(scenario.buildings) (moves.h).
Placement ApplyJointDisplacement(const Scenario& scenario, const Obstacles& buildings,
                                 const std::vector<Vec3>& displacements, const Placement& from);

// UAV `uav`'s observation: the scenario's env.observations (ObservationBounds) with `uav` as
// the active UAV (its one-hot, with several UAVs).
std::vector<double> AgentObservation(const Scenario& scenario, const StepInfo& info,
                                     std::size_t uav);

// The global state, independent of env.observations, bounds in StateBounds:
//   per UAV in scenario order: x, y, z                      (its zone)
//   per UE in scenario order: LoS to its serving UAV (0/1),   [0, 1]
//                             SNR to it in dB (clipped),     [-20, 60]
//                             the serving UAV's index        [0, UAVs - 1]
//   then the throughput in Mbit/s (clipped)                  [0, total demand]
//   and the number of UEs whose demand is met                [0, UEs]
// 3 x UAVs + 3 x UEs + 2 values.
BoxSpace StateBounds(const Scenario& scenario);
std::vector<double> MakeState(const Scenario& scenario, const StepInfo& info);

}  // namespace rlpos
