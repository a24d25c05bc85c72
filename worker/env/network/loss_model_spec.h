#pragma once
// The scenario's propagation loss model ({"type": "ns3::...", "attributes": {...}}) as an ns-3
// object, tuned to the channel: what the packet-level channel and the analytic model both use.
#include <ns3/propagation-loss-model.h>

#include "common/scenario/scenario.h"

namespace rlpos {

// Creates /propagation (a ConfigError names a bad type or attribute) and sets every model in
// it that has a "Frequency" attribute the scenario leaves unset to `frequency_hz`.
ns3::Ptr<ns3::PropagationLossModel> CreateLossModel(const Scenario& scenario, double frequency_hz);

}  // namespace rlpos
