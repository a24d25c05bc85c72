#pragma once
// The links a map draws, found as `rlpos-sim validate` finds them: the scenario built in ns-3
// (not run) at a placement gives each UE's serving UAV (environment/association.h) and its
// geometric LoS to it.
#include <vector>

#include "common/scenario/scenario.h"
#include "worker/map/map_scene.h"

namespace rlpos::map {

std::vector<MapLink> LinksAt(const Scenario& scenario, const Placement& placement);

// Sets every placement's n_los and, for a map of one placement, the scene's links. Throws
// ConfigError on a scenario ns-3 refuses, std::invalid_argument on a placement of another size.
void AddLinks(MapScene& scene);

}  // namespace rlpos::map
