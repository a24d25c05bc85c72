#pragma once
// UavNetwork's inside, shared by the files that build and run it: uav_network.cc (the network,
// its nodes and addresses, the links), uav_network_wifi.cc (the radios), uav_network_flows.cc
// (the UEs' flows) and uav_network_handover.cc (moving a flow to another UAV).
#include <ns3/application.h>
#include <ns3/mac48-address.h>
#include <ns3/mobility-model.h>
#include <ns3/net-device-container.h>
#include <ns3/node-container.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/random-variable-stream.h>
#include <ns3/ssid.h>
#include <ns3/wifi-helper.h>
#include <ns3/wifi-mac-helper.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-tx-vector.h>
#include <ns3/yans-wifi-helper.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "worker/env/network/obstacles_channel_condition_model.h"
#include "worker/env/network/traffic_monitor.h"
#include "worker/env/network/uav_network.h"
#include "worker/env/network/wifi_channel_plan.h"

namespace rlpos {

constexpr uint16_t kFirstPort = 9000;
// Far above what AssignStreams hands out to the network's models.
constexpr int64_t kStartTimesStream = 1000000;
// The senders that flows restarted after a handover get, two streams each, in handover order.
constexpr int64_t kHandoverStreams = 2000000;

inline ns3::Vector ToNs3(const Vec3& v) {
  return {v.x, v.y, v.z};
}
inline Vec3 FromNs3(const ns3::Vector& v) {
  return {v.x, v.y, v.z};
}

// Held by every UavNetwork: ns-3's simulator, node list and building list are process-wide, so
// a second network alive at once would tear down the first (Simulator::Destroy). Throws
// std::runtime_error when one is alive already.
class OneNetworkPerProcess {
 public:
  OneNetworkPerProcess();
  ~OneNetworkPerProcess();
  OneNetworkPerProcess(const OneNetworkPerProcess&) = delete;
  OneNetworkPerProcess& operator=(const OneNetworkPerProcess&) = delete;
};

struct UavNetwork::Impl {
  OneNetworkPerProcess token;  // first: released last, and before anything is built
  Scenario scenario;
  std::vector<WifiChannelPlan> plans;  // per UAV
  std::vector<int> channels;           // per UAV: its channel number
  ns3::Ptr<ns3::PropagationLossModel> loss;
  ns3::Ptr<ns3::ObstaclesChannelConditionModel> geometry;  // LoS for Link(), as the loss asks
  ns3::NodeContainer ues;
  ns3::NodeContainer uavs;
  std::vector<ns3::Ptr<ns3::WifiNetDevice>> uav_devices;
  bool handover = false;  // built with a radio per UAV on every UE (Reassociate allowed)
  bool uavs_fly = false;  // UavMotion::kFlies: waypoint mobility, moved by FlyUav
  std::vector<int64_t> last_waypoint_ns;  // per UAV: the time of its last waypoint (kFlies)
  // Per UE, per UAV: its radio linked to that UAV. Without handover only the serving UAV's.
  std::vector<std::vector<ns3::Ptr<ns3::WifiNetDevice>>> ue_devices;
  std::vector<ns3::Ipv4Address> uav_addresses;
  std::vector<int> serving;   // per UE: the index of its UAV
  std::vector<bool> joining;  // per UE: handed over, its flow waits for its radio to associate
  std::size_t handovers = 0;
  int64_t handover_streams = kHandoverStreams;      // the next restarted sender's first stream
  ns3::Ptr<ns3::ErrorRateModel> error_model;        // a twin of the PHYs' own (kErrorRateModel)
  std::vector<ns3::Ptr<ns3::Application>> senders;  // per UE: the sender of its current flow
  ns3::Ptr<ns3::UniformRandomVariable> start_times;
  std::map<std::pair<int, std::size_t>, ns3::Ptr<ns3::Application>> sinks;  // (UAV, UE)
  std::unique_ptr<TrafficMonitor> traffic;

  ns3::Ptr<ns3::MobilityModel> UavMobility(std::size_t u) const {
    return uavs.Get(static_cast<uint32_t>(u))->GetObject<ns3::MobilityModel>();
  }
  ns3::Ssid SsidOf(std::size_t u) const { return ns3::Ssid("rlpos-" + scenario.uavs[u].name); }
  ns3::Ptr<ns3::WifiNetDevice> RadioOf(std::size_t ue, std::size_t u) const {
    return handover ? ue_devices[ue][u] : ue_devices[ue][0];
  }
  bool Tcp() const { return scenario.traffic.protocol == "tcp_bulk"; }
  std::string SocketFactory() const {
    return Tcp() ? "ns3::TcpSocketFactory" : "ns3::UdpSocketFactory";
  }

  // The network, in the order it is built (uav_network.cc).
  void BuildChannelModels();
  void BuildNodes(const Placement& placement);  // UEs and UAVs, placed, in the buildings
  void InstallInternet(const ns3::NetDeviceContainer& devices);  // stacks and addresses
  void AssignStreams(ns3::WifiHelper& wifi, const ns3::NetDeviceContainer& devices);

  // The links (uav_network.cc).
  LinkState Link(uint32_t ue, std::size_t u) const;  // UE `ue`'s uplink to UAV `u`, now
  double SnrDb(uint32_t ue, std::size_t u) const;    // its SNR alone
  std::vector<LinkState> LinksTo(std::size_t u) const;
  std::vector<std::vector<double>> SnrTable() const;  // [UAV][UE], now

  // The radios (uav_network_wifi.cc): the UAVs' first, then the UEs'.
  ns3::NetDeviceContainer InstallWifi(ns3::WifiHelper& wifi);
  using PhyOf = std::function<ns3::YansWifiPhyHelper(std::size_t u)>;  // on UAV u's channel
  ns3::NetDeviceContainer InstallUavRadios(ns3::WifiHelper& wifi, const PhyOf& phy_of,
                                           ns3::WifiMacHelper& mac);
  ns3::NetDeviceContainer InstallUeRadios(ns3::WifiHelper& wifi, const PhyOf& phy_of,
                                          ns3::WifiMacHelper& mac);
  ns3::WifiTxVector TxVector(int mcs) const;  // single-user, the configured PHY

  // The UEs' flows (uav_network_flows.cc).
  void InstallApplications();
  // UE `ue`'s sink on UAV `u`, installed (and counted as the UE's) on first use.
  void EnsureSink(int u, std::size_t ue);
  // A sender from UE `ue` to its sink on UAV `u`, counted as the UE's; not yet started.
  ns3::Ptr<ns3::Application> InstallSender(std::size_t ue, int u);

  // The handover (uav_network_handover.cc).
  void ConnectAssociationTraces();
  void HandOver(std::size_t ue, int to);
  void OnRadioAssociated(std::size_t ue, std::size_t u, ns3::Mac48Address bssid);
  void RestartFlow(std::size_t ue);
};

}  // namespace rlpos
