#include "worker/env/analytic/analytic_channel.h"

#include <ns3/buildings-channel-condition-model.h>
#include <ns3/buildings-propagation-loss-model.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/pointer.h>
#include <ns3/propagation-loss-model.h>

#include <mutex>
#include <stdexcept>
#include <string>

#include "common/config/config_error.h"
#include "common/scenario/building_obstacles.h"
#include "worker/env/network/loss_model_spec.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/obstacle_aware_propagation_loss_model.h"
#include "worker/env/network/obstacles_channel_condition_model.h"
#include "worker/env/network/wifi_channel_plan.h"

namespace rlpos {
namespace {

ns3::Ptr<ns3::PropagationLossModel> SubModel(const ns3::Ptr<ns3::Object>& owner,
                                             const char* attribute) {
  ns3::PointerValue value;
  owner->GetAttribute(attribute, value);
  return value.Get<ns3::PropagationLossModel>();
}

// The analytic model calls a loss model with two bare mobility models, once per link, and
// needs the same answer for the same link: no building list, no random draws.
void CheckCallable(const ns3::Ptr<ns3::PropagationLossModel>& model, const std::string& path) {
  const std::string type = model->GetInstanceTypeId().GetName();
  if (ns3::DynamicCast<ns3::BuildingsPropagationLossModel>(model)) {
    throw ConfigError(path, type +
                                " reads ns-3's process-wide building list, which the analytic "
                                "fidelity does not build; use packet fidelity");
  }
  ns3::TypeId::AttributeInformation info;
  if (model->GetInstanceTypeId().LookupAttributeByName("ChannelConditionModel", &info) &&
      !ns3::DynamicCast<ns3::ObstacleAwarePropagationLossModel>(model)) {
    throw ConfigError(path, type +
                                " asks a channel condition model of its own; the analytic "
                                "fidelity decides LoS from the buildings; use packet fidelity");
  }
}

}  // namespace

// The scenario's loss model, and the two ends of a link. The obstacle-aware model is given the
// LoS from the value's own geometry (its condition model would ask ns-3's building list).
struct AnalyticChannel::LossModels {
  ns3::Ptr<ns3::PropagationLossModel> top;
  ns3::Ptr<ns3::ObstacleAwarePropagationLossModel> aware;  // top, when it is obstacle-aware
  ns3::Ptr<ns3::MobilityModel> ue;
  ns3::Ptr<ns3::MobilityModel> uav;
};

AnalyticChannel::AnalyticChannel(const Scenario& scenario)
    : geometry_(BuildingObstacles(scenario.buildings)),
      tx_dbm_(scenario.wifi.tx_power_dbm + scenario.wifi.antenna_gain_dbi),
      rx_gain_db_(scenario.wifi.antenna_gain_dbi),
      noise_floor_dbm_(scenario.wifi.noise_floor_dbm) {
  for (const auto& ue : scenario.ues)
    ues_.push_back(ue.position);
  std::lock_guard<std::mutex> lock(Ns3ObjectsMutex());
  const std::vector<WifiChannelPlan> plans = PlanUavChannels(scenario);
  for (const auto& plan : plans)
    channels_.push_back(plan.channel);
  auto loss = std::make_unique<LossModels>();
  // The first UAV's frequency for every channel, as the packet-level channel has it.
  loss->top = CreateLossModel(scenario, plans[0].center_frequency_hz);
  const std::string path = "/propagation";
  if (auto aware = ns3::DynamicCast<ns3::ObstacleAwarePropagationLossModel>(loss->top)) {
    ns3::PointerValue condition;
    aware->GetAttribute("ChannelConditionModel", condition);
    // It decides LoS from the venue's obstacles, which is what either model does (ns-3's own for
    // box buildings only: the scenario checks refuse it with footprints).
    if (!condition.Get<ns3::ObstaclesChannelConditionModel>() &&
        !condition.Get<ns3::BuildingsChannelConditionModel>()) {
      throw ConfigError(path + "/attributes/ChannelConditionModel",
                        "the analytic fidelity decides LoS from the buildings: "
                        "ns3::ObstaclesChannelConditionModel or "
                        "ns3::BuildingsChannelConditionModel only; use packet fidelity");
    }
    loss->aware = aware;
    CheckCallable(SubModel(aware, "LosModel"), path + "/attributes/LosModel");
    CheckCallable(SubModel(aware, "NlosModel"), path + "/attributes/NlosModel");
  } else {
    CheckCallable(loss->top, path);
  }
  // Fixed streams, as the packet-level network assigns them; a model that uses any would give
  // another number for the same link at every call.
  if (loss->top->AssignStreams(0) > 0) {
    throw ConfigError(path, loss->top->GetInstanceTypeId().GetName() +
                                " draws random numbers: the analytic fidelity needs one loss per "
                                "link and position; use packet fidelity");
  }
  loss->ue = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  loss->uav = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  loss_ = std::move(loss);
  rates_ = std::make_unique<McsErrorRates>(scenario);
}

AnalyticChannel::~AnalyticChannel() {
  std::lock_guard<std::mutex> lock(Ns3ObjectsMutex());
  loss_.reset();
  rates_.reset();
}

UplinkState AnalyticChannel::Uplink(std::size_t ue, const Vec3& uav) {
  const Vec3& p = ues_.at(ue);
  UplinkState link;
  link.los = geometry_.Los(p, uav);  // sender first, as the channel asks
  link.snr_db = SnrDb(p, uav, link.los);
  return link;
}

void AnalyticChannel::SetUePositions(const std::vector<Vec3>& positions) {
  if (positions.size() != ues_.size()) {
    throw std::invalid_argument(std::to_string(positions.size()) + " UE positions for " +
                                std::to_string(ues_.size()) + " UEs");
  }
  ues_ = positions;
}

double AnalyticChannel::SnrDb(const Vec3& ue, const Vec3& uav, bool los) {
  LossModels& m = *loss_;
  m.ue->SetPosition({ue.x, ue.y, ue.z});
  m.uav->SetPosition({uav.x, uav.y, uav.z});
  const double rx_dbm = m.aware ? m.aware->CalcRxPowerGivenLos(tx_dbm_, m.ue, m.uav, los)
                                : m.top->CalcRxPower(tx_dbm_, m.ue, m.uav);
  return rx_dbm + rx_gain_db_ - noise_floor_dbm_;
}

}  // namespace rlpos
