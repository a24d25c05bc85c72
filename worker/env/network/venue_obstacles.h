#pragma once
// The venue's buildings for the packet level: one Obstacles (common/geometry) that decides every
// link's LoS, handed to each ns3::ObstaclesChannelConditionModel of the loss model; and ns-3's own
// Building objects, for ns-3's models that look them up (they know boxes only).
#include <ns3/object.h>

#include <memory>
#include <string>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// Gives `obstacles` to every ns3::ObstaclesChannelConditionModel in `loss`'s tree (objects
// reachable through pointer attributes). When the scenario has footprint buildings, a model
// that reads ns-3's own buildings (BuildingsChannelConditionModel, a BuildingsPropagationLossModel)
// would see none of them: ConfigError at `path`.
void GiveObstacles(const Scenario& scenario, ns3::Ptr<ns3::Object> loss,
                   const std::shared_ptr<const Obstacles>& obstacles, const std::string& path);

// ns-3 Building objects for the box buildings (footprint buildings have no ns-3 form). ns-3's
// building list is process-wide: one network per process (OneNetworkPerProcess).
void BuildNs3Buildings(const Scenario& scenario);

}  // namespace rlpos
