#pragma once
// A UE's mobility in words, for summaries: "random_waypoint at 0.5-1.5 m/s, pause 2 s".
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

std::string DescribeMobility(const MobilitySpec& mobility);

}  // namespace rlpos
