#include "common/scenario_generator/hidden_ues.h"

#include "common/scenario/building_obstacles.h"

namespace rlpos {

int UesHiddenFromAll(const Scenario& scenario, const Placement& placement) {
  const Obstacles obstacles = BuildingObstacles(scenario.buildings);
  int hidden = 0;
  for (const auto& ue : scenario.ues) {
    bool seen = false;
    for (const auto& uav : placement)
      seen = seen || !obstacles.Blocked(ue.position, uav);
    hidden += seen ? 0 : 1;
  }
  return hidden;
}

}  // namespace rlpos
