#include "worker/env/network/obstacle_aware_propagation_loss_model.h"

#include <ns3/boolean.h>
#include <ns3/itu-r-1411-los-propagation-loss-model.h>
#include <ns3/itu-r-1411-nlos-over-rooftop-propagation-loss-model.h>
#include <ns3/log.h>
#include <ns3/mobility-model.h>
#include <ns3/pointer.h>

#include <algorithm>
#include <utility>

#include "worker/env/network/obstacles_channel_condition_model.h"

namespace ns3 {

NS_LOG_COMPONENT_DEFINE("ObstacleAwarePropagationLossModel");
NS_OBJECT_ENSURE_REGISTERED(ObstacleAwarePropagationLossModel);

TypeId ObstacleAwarePropagationLossModel::GetTypeId() {
  static TypeId tid =
      TypeId("ns3::ObstacleAwarePropagationLossModel")
          .SetParent<PropagationLossModel>()
          .SetGroupName("Rlpos")
          .AddConstructor<ObstacleAwarePropagationLossModel>()
          .AddAttribute(
              "LosModel", "Loss model applied to line-of-sight links (default ItuR1411Los).",
              PointerValue(), MakePointerAccessor(&ObstacleAwarePropagationLossModel::m_losModel),
              MakePointerChecker<PropagationLossModel>())
          .AddAttribute(
              "NlosModel",
              "Loss model applied to links a building obstructs (default ItuR1411NlosOverRooftop).",
              PointerValue(), MakePointerAccessor(&ObstacleAwarePropagationLossModel::m_nlosModel),
              MakePointerChecker<PropagationLossModel>())
          .AddAttribute(
              "NlosNeverBelowLos", "Clamp the NLoS loss to at least the LoS loss of the same link.",
              BooleanValue(true),
              MakeBooleanAccessor(&ObstacleAwarePropagationLossModel::m_nlosNeverBelowLos),
              MakeBooleanChecker())
          .AddAttribute(
              "ChannelConditionModel",
              "Decides LoS or NLoS per link (default ObstaclesChannelConditionModel: the venue's "
              "buildings, boxes or footprints).",
              PointerValue(),
              MakePointerAccessor(&ObstacleAwarePropagationLossModel::m_conditionModel),
              MakePointerChecker<ChannelConditionModel>());
  return tid;
}

ObstacleAwarePropagationLossModel::ObstacleAwarePropagationLossModel() = default;

void ObstacleAwarePropagationLossModel::NotifyConstructionCompleted() {
  // Defaults are made here, per instance: an attribute's initial value object would be shared
  // by every instance (and so would a Frequency set on it).
  if (!m_losModel)
    m_losModel = CreateObject<ItuR1411LosPropagationLossModel>();
  if (!m_nlosModel)
    m_nlosModel = CreateObject<ItuR1411NlosOverRooftopPropagationLossModel>();
  if (!m_conditionModel)
    m_conditionModel = CreateObject<ObstaclesChannelConditionModel>();
  PropagationLossModel::NotifyConstructionCompleted();
}

bool ObstacleAwarePropagationLossModel::IsLos(Ptr<MobilityModel> a, Ptr<MobilityModel> b) const {
  return m_conditionModel->GetChannelCondition(a, b)->IsLos();
}

double ObstacleAwarePropagationLossModel::GetLossDb(Ptr<MobilityModel> a,
                                                    Ptr<MobilityModel> b) const {
  return -DoCalcRxPower(0.0, a, b);
}

double ObstacleAwarePropagationLossModel::DoCalcRxPower(double txPowerDbm, Ptr<MobilityModel> a,
                                                        Ptr<MobilityModel> b) const {
  const bool los = IsLos(a, b);
  NS_LOG_DEBUG("link " << a->GetPosition() << " -> " << b->GetPosition() << ": "
                       << (los ? "LoS" : "NLoS"));
  return CalcRxPowerGivenLos(txPowerDbm, a, b, los);
}

double ObstacleAwarePropagationLossModel::CalcRxPowerGivenLos(double txPowerDbm,
                                                              Ptr<MobilityModel> a,
                                                              Ptr<MobilityModel> b,
                                                              bool los) const {
  // The sub-models always see the higher end first, so that the link is reciprocal. ns-3.37's
  // ItuR1411NlosOverRooftop is not: below the rooftops it takes the first node's height where
  // ITU-R P.1411 has the rooftop height (kd = 18 - 15 dhb / hr), and a UE 1.5 m up transmitting
  // to a UAV under the roofs lost ~20 dB less than the UAV transmitting back.
  if (b->GetPosition().z > a->GetPosition().z)
    std::swap(a, b);
  // CalcRxPower (not DoCalcRxPower) so that a chained Next model of the sub-model applies too.
  const double los_rx = m_losModel->CalcRxPower(txPowerDbm, a, b);
  if (los)
    return los_rx;
  const double nlos_rx = m_nlosModel->CalcRxPower(txPowerDbm, a, b);
  // ITU-R P.1411 over-rooftop NLoS is meant for a transmitter above the rooftops; below them,
  // at short range, its loss can fall under the LoS model's. A building in the way never helps.
  return m_nlosNeverBelowLos ? std::min(los_rx, nlos_rx) : nlos_rx;
}

int64_t ObstacleAwarePropagationLossModel::DoAssignStreams(int64_t stream) {
  int64_t used = m_losModel->AssignStreams(stream);
  used += m_nlosModel->AssignStreams(stream + used);
  used += m_conditionModel->AssignStreams(stream + used);
  return used;
}

void ObstacleAwarePropagationLossModel::DoDispose() {
  m_losModel = nullptr;
  m_nlosModel = nullptr;
  m_conditionModel = nullptr;
  PropagationLossModel::DoDispose();
}

}  // namespace ns3
