#pragma once
// A placement as rlpos-sim's JSON results write it: [[x, y, z], ...], one per UAV in the
// scenario's order (store/job_result.h reads it back).
#include <nlohmann/json.hpp>

#include "common/scenario/scenario.h"

namespace rlpos {

nlohmann::json PlacementJson(const Placement& placement);

}  // namespace rlpos
