#pragma once
// The UEs' mobility models at packet level: a constant position for a static UE, else ns-3's
// WaypointMobilityModel playing the UE's trajectory (common/mobility), so ns-3 sees exactly the
// positions the analytic fidelity computes, and draws nothing from ns-3's random streams.
#include <ns3/node-container.h>

#include "common/scenario/scenario.h"

namespace rlpos {

// Installs one mobility model on each node of `ues` (scenario.ues' order). Throws ConfigError
// when a UE's trajectory cannot be drawn (common/mobility/ue_trajectories.h).
void InstallUeMobility(const Scenario& scenario, ns3::NodeContainer& ues);

}  // namespace rlpos
