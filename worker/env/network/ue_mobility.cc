#include "worker/env/network/ue_mobility.h"

#include <ns3/mobility-helper.h>
#include <ns3/nstime.h>
#include <ns3/waypoint-mobility-model.h>

#include <cmath>

#include "common/mobility/ue_trajectories.h"

namespace rlpos {
namespace {

ns3::Vector ToVector(const Vec3& v) {
  return {v.x, v.y, v.z};
}

}  // namespace

void InstallUeMobility(const Scenario& scenario, ns3::NodeContainer& ues) {
  const auto trajectories = UeTrajectories(scenario);
  for (std::size_t i = 0; i < scenario.ues.size(); ++i) {
    const auto node = ues.Get(static_cast<uint32_t>(i));
    ns3::MobilityHelper mobility;
    if (scenario.ues[i].mobility.model == MobilityModel::kStatic) {
      mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
      mobility.Install(node);
      node->GetObject<ns3::MobilityModel>()->SetPosition(ToVector(scenario.ues[i].position));
      continue;
    }
    mobility.SetMobilityModel("ns3::WaypointMobilityModel");
    mobility.Install(node);
    auto waypoints = node->GetObject<ns3::WaypointMobilityModel>();
    // Times are whole nanoseconds (the trajectory's own), so each knot lands on ns-3's grid.
    for (const Waypoint& w : trajectories[i].waypoints()) {
      waypoints->AddWaypoint(
          ns3::Waypoint(ns3::NanoSeconds(std::llround(w.time * 1e9)), ToVector(w.position)));
    }
  }
}

}  // namespace rlpos
