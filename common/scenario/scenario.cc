#include "scenario/scenario.h"

namespace rlpos {

double Scenario::TotalDemandMbps() const {
  double total = 0.0;
  for (const auto& ue : ues) total += ue.demand_mbps;
  return total;
}

ObjectSpec DefaultPropagation() {
  return {"ns3::ObstacleAwarePropagationLossModel",
          {{"LosModel", {{"type", "ns3::ItuR1411LosPropagationLossModel"}}},
           {"NlosModel", {{"type", "ns3::ItuR1411NlosOverRooftopPropagationLossModel"}}}}};
}

}  // namespace rlpos
