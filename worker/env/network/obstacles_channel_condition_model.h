#pragma once
// ns3::ObstaclesChannelConditionModel: LoS or NLoS by the venue's obstacles (rlpos::Obstacles,
// common/geometry), the one geometry every part of RLpos uses, so that footprint buildings block
// the packet level exactly as they block the analytic model, the oracle and the maps. For box
// buildings it decides as ns3::BuildingsChannelConditionModel does, to the last bit: both ends
// outdoors, LoS unless a building is in between (O2O); both indoors, LoS only in the same
// building (I2I); one of each, NLoS (O2I). It draws no random numbers.
#include <ns3/channel-condition-model.h>

#include <memory>

#include "common/geometry/obstacles.h"

namespace ns3 {

class ObstaclesChannelConditionModel : public ChannelConditionModel {
 public:
  static TypeId GetTypeId();

  // The venue's obstacles. Until they are set, the model reads ns-3's own buildings
  // (ns3::BuildingList, boxes), as BuildingsChannelConditionModel does, so that it also works
  // in a plain ns-3 program.
  void SetObstacles(std::shared_ptr<const rlpos::Obstacles> obstacles);

  Ptr<ChannelCondition> GetChannelCondition(Ptr<const MobilityModel> a,
                                            Ptr<const MobilityModel> b) const override;
  int64_t AssignStreams(int64_t stream) override;

 private:
  const rlpos::Obstacles& CurrentObstacles() const;

  std::shared_ptr<const rlpos::Obstacles> m_obstacles;
  // Without SetObstacles: the boxes of ns3::BuildingList, rebuilt when the list grows.
  mutable std::shared_ptr<const rlpos::Obstacles> m_listObstacles;
  mutable uint32_t m_listSize = 0;
};

}  // namespace ns3
