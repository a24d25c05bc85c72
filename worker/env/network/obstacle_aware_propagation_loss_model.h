#pragma once
// ns3::ObstacleAwarePropagationLossModel: per link, asks a channel condition model (by default
// ns3::ObstaclesChannelConditionModel, the venue's buildings as boxes or footprints, given by
// the network that builds it) whether the link is LoS, and applies the LoS or the NLoS loss model
// accordingly.
//
// Why not ns3::HybridBuildingsPropagationLossModel: between two outdoor nodes it switches
// between ITU-R P.1411 LoS and NLoS by distance, never by geometry, so the throughput of a link
// would not change when a building comes between the two ends.
#include <ns3/channel-condition-model.h>
#include <ns3/propagation-loss-model.h>

namespace ns3 {

class ObstacleAwarePropagationLossModel : public PropagationLossModel {
 public:
  static TypeId GetTypeId();
  ObstacleAwarePropagationLossModel();

  // True when the channel condition model calls the link line-of-sight.
  bool IsLos(Ptr<MobilityModel> a, Ptr<MobilityModel> b) const;
  // The loss (dB) this model applies to the link.
  double GetLossDb(Ptr<MobilityModel> a, Ptr<MobilityModel> b) const;
  // The received power with the link's LoS state given, not asked of the condition model: what
  // the analytic fidelity calls with the LoS its own building geometry decides.
  double CalcRxPowerGivenLos(double txPowerDbm, Ptr<MobilityModel> a, Ptr<MobilityModel> b,
                             bool los) const;

 private:
  void NotifyConstructionCompleted() override;
  double DoCalcRxPower(double txPowerDbm, Ptr<MobilityModel> a,
                       Ptr<MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t stream) override;
  void DoDispose() override;

  Ptr<PropagationLossModel> m_losModel;
  Ptr<PropagationLossModel> m_nlosModel;
  Ptr<ChannelConditionModel> m_conditionModel;
  bool m_nlosNeverBelowLos = true;
};

}  // namespace ns3
