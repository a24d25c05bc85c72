#include "worker/env/network/obstacles_channel_condition_model.h"

#include <ns3/abort.h>
#include <ns3/mobility-model.h>

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

Ptr<ChannelCondition> ObstaclesChannelConditionModel::GetChannelCondition(
    Ptr<const MobilityModel> a, Ptr<const MobilityModel> b) const {
  NS_ABORT_MSG_IF(!m_obstacles, "ObstaclesChannelConditionModel: no obstacles set");
  const Vector pa = a->GetPosition();
  const Vector pb = b->GetPosition();
  const rlpos::Vec3 ra{pa.x, pa.y, pa.z};
  const rlpos::Vec3 rb{pb.x, pb.y, pb.z};
  const int in_a = m_obstacles->SolidAt(ra);
  const int in_b = m_obstacles->SolidAt(rb);
  ChannelCondition::O2iConditionValue o2i = ChannelCondition::O2O;
  if (in_a >= 0 && in_b >= 0)
    o2i = ChannelCondition::I2I;
  else if (in_a >= 0 || in_b >= 0)
    o2i = ChannelCondition::O2I;
  const bool los = m_obstacles->Los(ra, rb);
  return CreateObject<ChannelCondition>(los ? ChannelCondition::LOS : ChannelCondition::NLOS, o2i);
}

int64_t ObstaclesChannelConditionModel::AssignStreams(int64_t /*stream*/) {
  return 0;
}

}  // namespace ns3
