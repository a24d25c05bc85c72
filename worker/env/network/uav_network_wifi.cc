// The radios of the UAV network: a Yans channel per channel number, the PHY and standard the
// scenario configures, an AP (or ad hoc) radio per UAV and a STA (or ad hoc) radio per UE and
// serving UAV, and the rate managers' attributes.
#include <ns3/boolean.h>
#include <ns3/double.h>
#include <ns3/propagation-delay-model.h>
#include <ns3/string.h>
#include <ns3/uinteger.h>
#include <ns3/wifi-remote-station-manager.h>
#include <ns3/yans-wifi-channel.h>

#include <limits>
#include <map>

#include "worker/env/network/block_ack_guard.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/uav_network_impl.h"

namespace rlpos {
namespace {

// One Yans channel per channel number: the BSSs of UAVs on the same channel hear (and
// interfere with) each other, those on distinct channels do not (no adjacent-channel leakage).
std::map<int, ns3::Ptr<ns3::YansWifiChannel>> BuildAir(
    const std::vector<int>& channels, const ns3::Ptr<ns3::PropagationLossModel>& loss) {
  std::map<int, ns3::Ptr<ns3::YansWifiChannel>> air;
  for (int number : channels) {
    if (air.count(number))
      continue;
    auto channel = ns3::CreateObject<ns3::YansWifiChannel>();
    channel->SetPropagationLossModel(loss);
    channel->SetPropagationDelayModel(ns3::CreateObject<ns3::ConstantSpeedPropagationDelayModel>());
    air[number] = channel;
  }
  return air;
}

// The PHY every radio shares, before its channel is set.
ns3::YansWifiPhyHelper CommonPhy(const WifiSpec& w, const WifiChannelPlan& plan) {
  ns3::YansWifiPhyHelper phy;
  phy.Set("TxPowerStart", ns3::DoubleValue(w.tx_power_dbm));
  phy.Set("TxPowerEnd", ns3::DoubleValue(w.tx_power_dbm));
  phy.Set("TxGain", ns3::DoubleValue(w.antenna_gain_dbi));
  phy.Set("RxGain", ns3::DoubleValue(w.antenna_gain_dbi));
  phy.Set("RxNoiseFigure", ns3::DoubleValue(plan.rx_noise_figure_db));
  phy.Set("Antennas", ns3::UintegerValue(w.spatial_streams));
  phy.Set("MaxSupportedTxSpatialStreams", ns3::UintegerValue(w.spatial_streams));
  phy.Set("MaxSupportedRxSpatialStreams", ns3::UintegerValue(w.spatial_streams));
  phy.SetErrorRateModel(kErrorRateModel);
  return phy;
}

void ConfigureStandard(ns3::WifiHelper& wifi, const WifiSpec& w, ns3::WifiStandard standard) {
  wifi.SetStandard(standard);
  wifi.SetRemoteStationManager(w.rate_manager.type);
  if (standard == ns3::WIFI_STANDARD_80211ax) {
    wifi.ConfigHeOptions("GuardInterval", ns3::TimeValue(ns3::NanoSeconds(w.guard_interval_ns)));
  } else {
    wifi.ConfigHtOptions("ShortGuardIntervalSupported",
                         ns3::BooleanValue(w.guard_interval_ns == 400));
  }
}

// Rate manager attributes and RTS/CTS are set per instance: Config::SetDefault would leak
// into every later network built in the same process.
void ConfigureRateManagers(const ns3::NetDeviceContainer& devices, const WifiSpec& w) {
  for (uint32_t i = 0; i < devices.GetN(); ++i) {
    auto manager = ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i))->GetRemoteStationManager();
    for (auto it = w.rate_manager.attributes.begin(); it != w.rate_manager.attributes.end(); ++it) {
      manager->SetAttribute(it.key(), ns3::StringValue(AttributeString(*it)));
    }
    // Off keeps ns-3's own threshold (larger than any PSDU): 65535 would still protect long
    // A-MPDUs with RTS/CTS.
    if (w.rts_cts)
      manager->SetAttribute("RtsCtsThreshold", ns3::UintegerValue(0));
  }
}

}  // namespace

ns3::WifiTxVector UavNetwork::Impl::TxVector(int mcs) const {
  return SingleUserTxVector(plans[0], scenario.wifi, mcs);
}

ns3::NetDeviceContainer UavNetwork::Impl::InstallWifi(ns3::WifiHelper& wifi) {
  const WifiSpec& w = scenario.wifi;
  // Validates the rate manager spec (type, attributes) before ns-3 would abort on it.
  CreateFromSpec(w.rate_manager, "/wifi/rate_manager", ns3::WifiRemoteStationManager::GetTypeId());
  std::map<int, ns3::Ptr<ns3::YansWifiChannel>> air = BuildAir(channels, loss);
  ns3::YansWifiPhyHelper phy = CommonPhy(w, plans[0]);
  // The PHY of a node served by (or being) UAV u: on u's channel.
  const PhyOf phy_of = [&](std::size_t u) {
    phy.SetChannel(air[channels[u]]);
    phy.Set("ChannelSettings", ns3::StringValue(plans[u].channel_settings));
    return phy;
  };
  ConfigureStandard(wifi, w, plans[0].standard);
  // UAVs first, then the UEs, each in the scenario's order (the addresses follow it).
  ns3::WifiMacHelper mac;
  ns3::NetDeviceContainer devices = InstallUavRadios(wifi, phy_of, mac);
  devices.Add(InstallUeRadios(wifi, phy_of, mac));
  ConfigureRateManagers(devices, w);
  // ns-3.37 mishandles an A-MPDU sent under a Block Ack agreement its recipient still holds as
  // pending (block_ack_guard.h).
  GuardBlockAckRecipients(devices);
  return devices;
}

ns3::NetDeviceContainer UavNetwork::Impl::InstallUavRadios(ns3::WifiHelper& wifi,
                                                           const PhyOf& phy_of,
                                                           ns3::WifiMacHelper& mac) {
  ns3::NetDeviceContainer devices;
  for (std::size_t u = 0; u < scenario.uavs.size(); ++u) {
    if (scenario.wifi.mode == "adhoc") {
      mac.SetType("ns3::AdhocWifiMac");
    } else {
      mac.SetType("ns3::ApWifiMac", "Ssid", ns3::SsidValue(SsidOf(u)));
    }
    devices.Add(wifi.Install(phy_of(u), mac, uavs.Get(static_cast<uint32_t>(u))));
  }
  return devices;
}

// Each UE: a radio linked to its serving UAV, or with handover one per UAV (in UAV order).
ns3::NetDeviceContainer UavNetwork::Impl::InstallUeRadios(ns3::WifiHelper& wifi,
                                                          const PhyOf& phy_of,
                                                          ns3::WifiMacHelper& mac) {
  ns3::NetDeviceContainer devices;
  ue_devices.assign(ues.GetN(), {});
  for (uint32_t i = 0; i < ues.GetN(); ++i) {
    for (std::size_t u = 0; u < scenario.uavs.size(); ++u) {
      if (!handover && u != static_cast<std::size_t>(serving[i]))
        continue;
      if (scenario.wifi.mode == "adhoc") {
        mac.SetType("ns3::AdhocWifiMac");
      } else if (handover || uavs_fly) {
        // The radios stay in their BSS: beacons lost in a saturated shared channel, or while a
        // UAV flies behind a building, must not drop one (ns-3.37 then flushes a MAC queue with
        // frames in flight, and crashes). Fixed UAVs without handover keep ns-3's default.
        mac.SetType("ns3::StaWifiMac", "Ssid", ns3::SsidValue(SsidOf(u)), "MaxMissedBeacons",
                    ns3::UintegerValue(std::numeric_limits<uint32_t>::max()));
      } else {
        mac.SetType("ns3::StaWifiMac", "Ssid", ns3::SsidValue(SsidOf(u)));
      }
      ns3::NetDeviceContainer radio = wifi.Install(phy_of(u), mac, ues.Get(i));
      ue_devices[i].push_back(ns3::DynamicCast<ns3::WifiNetDevice>(radio.Get(0)));
      devices.Add(radio);
    }
  }
  return devices;
}

}  // namespace rlpos
