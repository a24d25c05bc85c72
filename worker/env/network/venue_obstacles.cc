#include "worker/env/network/venue_obstacles.h"

#include <ns3/building.h>
#include <ns3/buildings-channel-condition-model.h>
#include <ns3/buildings-propagation-loss-model.h>

#include <algorithm>

#include "common/config/config_error.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/obstacles_channel_condition_model.h"

namespace rlpos {
namespace {

ns3::Building::BuildingType_t BuildingType(const std::string& type) {
  if (type == "office")
    return ns3::Building::Office;
  if (type == "commercial")
    return ns3::Building::Commercial;
  return ns3::Building::Residential;
}

ns3::Building::ExtWallsType_t WallsType(const std::string& walls) {
  if (walls == "wood")
    return ns3::Building::Wood;
  if (walls == "concrete_without_windows")
    return ns3::Building::ConcreteWithoutWindows;
  if (walls == "stone_blocks")
    return ns3::Building::StoneBlocks;
  return ns3::Building::ConcreteWithWindows;
}

bool ReadsNs3Buildings(const ns3::TypeId& tid) {
  return tid == ns3::BuildingsChannelConditionModel::GetTypeId() ||
         tid.IsChildOf(ns3::BuildingsPropagationLossModel::GetTypeId());
}

}  // namespace

void GiveObstacles(const Scenario& scenario, ns3::Ptr<ns3::Object> loss,
                   const std::shared_ptr<const Obstacles>& obstacles, const std::string& path) {
  const bool footprints = std::any_of(scenario.buildings.begin(), scenario.buildings.end(),
                                      [](const BuildingSpec& b) { return b.HasFootprint(); });
  VisitObjectTree(loss, [&](ns3::Ptr<ns3::Object> object) {
    if (auto model = ns3::DynamicCast<ns3::ObstaclesChannelConditionModel>(object)) {
      model->SetObstacles(obstacles);
    } else if (footprints && ReadsNs3Buildings(object->GetInstanceTypeId())) {
      throw ConfigError(path, object->GetInstanceTypeId().GetName() +
                                  " reads ns-3's buildings, which are boxes, and this scenario "
                                  "has footprint buildings: use "
                                  "ns3::ObstacleAwarePropagationLossModel with its default "
                                  "ChannelConditionModel (ns3::ObstaclesChannelConditionModel)");
    }
  });
}

void BuildNs3Buildings(const Scenario& scenario) {
  for (const auto& b : scenario.buildings) {
    if (b.HasFootprint())
      continue;
    auto building = ns3::CreateObject<ns3::Building>();
    building->SetBoundaries(ns3::Box(b.xmin, b.xmax, b.ymin, b.ymax, 0.0, b.height));
    building->SetBuildingType(BuildingType(b.type));
    building->SetExtWallsType(WallsType(b.walls));
    building->SetNFloors(static_cast<uint16_t>(b.floors));
    building->SetNRoomsX(static_cast<uint16_t>(b.rooms_x));
    building->SetNRoomsY(static_cast<uint16_t>(b.rooms_y));
  }
}

}  // namespace rlpos
