#include "worker/env/network/obstacles_channel_condition_model.h"

#include <ns3/building-list.h>
#include <ns3/building.h>
#include <ns3/mobility-model.h>

#include <utility>
#include <vector>

namespace ns3 {

NS_OBJECT_ENSURE_REGISTERED(ObstaclesChannelConditionModel);

TypeId ObstaclesChannelConditionModel::GetTypeId() {
  static TypeId tid = TypeId("ns3::ObstaclesChannelConditionModel")
                          .SetParent<ChannelConditionModel>()
                          .SetGroupName("Rlpos")
                          .AddConstructor<ObstaclesChannelConditionModel>();
  return tid;
}

void ObstaclesChannelConditionModel::SetObstacles(
    std::shared_ptr<const rlpos::Obstacles> obstacles) {
  m_obstacles = std::move(obstacles);
}

const rlpos::Obstacles& ObstaclesChannelConditionModel::CurrentObstacles() const {
  if (m_obstacles)
    return *m_obstacles;
  if (!m_listObstacles || BuildingList::GetNBuildings() != m_listSize) {
    std::vector<rlpos::Solid> solids;
    for (auto it = BuildingList::Begin(); it != BuildingList::End(); ++it) {
      const Box box = (*it)->GetBoundaries();
      solids.push_back(
          rlpos::Solid::OfBox({box.xMin, box.xMax, box.yMin, box.yMax, box.zMin, box.zMax}));
    }
    m_listObstacles = std::make_shared<const rlpos::Obstacles>(std::move(solids));
    m_listSize = BuildingList::GetNBuildings();
  }
  return *m_listObstacles;
}

Ptr<ChannelCondition> ObstaclesChannelConditionModel::GetChannelCondition(
    Ptr<const MobilityModel> a, Ptr<const MobilityModel> b) const {
  const rlpos::Obstacles& obstacles = CurrentObstacles();
  const Vector pa = a->GetPosition();
  const Vector pb = b->GetPosition();
  const rlpos::Vec3 ra{pa.x, pa.y, pa.z};
  const rlpos::Vec3 rb{pb.x, pb.y, pb.z};
  const int in_a = obstacles.SolidAt(ra);
  const int in_b = obstacles.SolidAt(rb);
  ChannelCondition::O2iConditionValue o2i = ChannelCondition::O2O;
  if (in_a >= 0 && in_b >= 0)
    o2i = ChannelCondition::I2I;
  else if (in_a >= 0 || in_b >= 0)
    o2i = ChannelCondition::O2I;
  const bool los = obstacles.Los(ra, rb);
  return CreateObject<ChannelCondition>(los ? ChannelCondition::LOS : ChannelCondition::NLOS, o2i);
}

int64_t ObstaclesChannelConditionModel::AssignStreams(int64_t /*stream*/) {
  return 0;
}

}  // namespace ns3
