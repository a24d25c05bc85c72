#include "common/scenario/scenario.h"

namespace rlpos {

double Scenario::TotalDemandMbps() const {
  double total = 0.0;
  for (const auto& ue : ues)
    total += ue.demand_mbps;
  return total;
}

Placement Scenario::InitialPlacement() const {
  Placement placement;
  for (const auto& uav : uavs)
    placement.push_back(uav.initial);
  return placement;
}

int Scenario::UavIndex(const std::string& name) const {
  for (std::size_t i = 0; i < uavs.size(); ++i) {
    if (uavs[i].name == name)
      return static_cast<int>(i);
  }
  return -1;
}

std::string Scenario::UavPath(std::size_t i) const {
  return uavs_listed ? "/uavs/" + std::to_string(i) : "/uav";
}

ObjectSpec DefaultPropagation() {
  return {"ns3::ObstacleAwarePropagationLossModel",
          {{"LosModel", {{"type", "ns3::ItuR1411LosPropagationLossModel"}}},
           {"NlosModel", {{"type", "ns3::ItuR1411NlosOverRooftopPropagationLossModel"}}}}};
}

}  // namespace rlpos
