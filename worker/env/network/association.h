#pragma once
// Which UAV serves each UE: the scenario's fixed assignment where a UE names its UAV, otherwise
// the UAV of the best SNR (the lowest index among equals). Pure data: the packet-level network
// and the analytic model decide the same way.
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// `snr_db[u][i]`: UE i's uplink SNR at UAV u. Returns the serving UAV's index per UE.
std::vector<int> AssociateUes(const Scenario& scenario,
                              const std::vector<std::vector<double>>& snr_db);

}  // namespace rlpos
