#pragma once
// The UEs that no UAV of a placement sees, by the one LoS rule (common/geometry/obstacles.h):
// the generator keeps a draw only when its baseline placement leaves some UE hidden.
#include "common/scenario/scenario.h"

namespace rlpos {

// The UEs whose links to every UAV of `placement` are blocked: NLoS whichever UAV serves them.
int UesHiddenFromAll(const Scenario& scenario, const Placement& placement);

}  // namespace rlpos
