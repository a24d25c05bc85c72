#include "worker/environment/uav_network.h"

#include <ns3/boolean.h>
#include <ns3/building.h>
#include <ns3/buildings-channel-condition-model.h>
#include <ns3/buildings-helper.h>
#include <ns3/bulk-send-application.h>
#include <ns3/bulk-send-helper.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/core-module.h>
#include <ns3/double.h>
#include <ns3/error-rate-model.h>
#include <ns3/he-phy.h>
#include <ns3/ht-phy.h>
#include <ns3/inet-socket-address.h>
#include <ns3/internet-stack-helper.h>
#include <ns3/ipv4-address-helper.h>
#include <ns3/mobility-helper.h>
#include <ns3/mobility-model.h>
#include <ns3/neighbor-cache-helper.h>
#include <ns3/on-off-helper.h>
#include <ns3/onoff-application.h>
#include <ns3/packet-sink-helper.h>
#include <ns3/propagation-delay-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/rectangle.h>
#include <ns3/ssid.h>
#include <ns3/sta-wifi-mac.h>
#include <ns3/vht-phy.h>
#include <ns3/wifi-helper.h>
#include <ns3/wifi-mac-helper.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-remote-station-manager.h>
#include <ns3/yans-wifi-channel.h>
#include <ns3/yans-wifi-helper.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "common/config/config_error.h"
#include "worker/environment/association.h"
#include "worker/environment/ns3_object_spec.h"
#include "worker/environment/traffic_monitor.h"
#include "worker/environment/wifi_channel_plan.h"

namespace rlpos {
namespace {

constexpr uint16_t kFirstPort = 9000;
// Far above what AssignStreams hands out to the network's models.
constexpr int64_t kStartTimesStream = 1000000;
// The senders that flows restarted after a handover get, two streams each, in handover order.
constexpr int64_t kHandoverStreams = 2000000;
// ns-3.37's default for HT/VHT/HE, named so that the analytic fidelity can build the same one.
constexpr char kErrorRateModel[] = "ns3::TableBasedErrorRateModel";

ns3::Vector ToNs3(const Vec3& v) {
  return {v.x, v.y, v.z};
}
Vec3 FromNs3(const ns3::Vector& v) {
  return {v.x, v.y, v.z};
}

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

void BuildBuildings(const Scenario& s) {
  for (const auto& b : s.buildings) {
    auto building = ns3::CreateObject<ns3::Building>();
    building->SetBoundaries(ns3::Box(b.xmin, b.xmax, b.ymin, b.ymax, 0.0, b.height));
    building->SetBuildingType(BuildingType(b.type));
    building->SetExtWallsType(WallsType(b.walls));
    building->SetNFloors(static_cast<uint16_t>(b.floors));
    building->SetNRoomsX(static_cast<uint16_t>(b.rooms_x));
    building->SetNRoomsY(static_cast<uint16_t>(b.rooms_y));
  }
}

void InstallUeMobility(const Scenario& s, ns3::NodeContainer& ues) {
  for (std::size_t i = 0; i < s.ues.size(); ++i) {
    const auto& ue = s.ues[i];
    ns3::MobilityHelper mobility;
    if (ue.mobility.model == "random_walk") {
      mobility.SetMobilityModel(
          "ns3::RandomWalk2dMobilityModel", "Bounds",
          ns3::RectangleValue(ns3::Rectangle(0, s.venue.width, 0, s.venue.depth)), "Mode",
          ns3::StringValue("Time"), "Time",
          ns3::TimeValue(ns3::Seconds(ue.mobility.change_interval)), "Speed",
          ns3::StringValue(
              "ns3::ConstantRandomVariable[Constant=" + AttributeString(ue.mobility.speed) + "]"));
    } else {
      mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
    }
    mobility.Install(ues.Get(i));
    ues.Get(i)->GetObject<ns3::MobilityModel>()->SetPosition(ToNs3(ue.position));
  }
}

}  // namespace

struct UavNetwork::Impl {
  Scenario scenario;
  std::vector<WifiChannelPlan> plans;  // per UAV
  std::vector<int> channels;           // per UAV: its channel number
  ns3::Ptr<ns3::PropagationLossModel> loss;
  ns3::Ptr<ns3::BuildingsChannelConditionModel> geometry;
  ns3::NodeContainer ues;
  ns3::NodeContainer uavs;
  std::vector<ns3::Ptr<ns3::WifiNetDevice>> uav_devices;
  bool handover = false;  // built with a radio per UAV on every UE (Reassociate allowed)
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
  void BuildChannelModels();
  LinkState Link(uint32_t ue, std::size_t u) const;  // UE `ue`'s uplink to UAV `u`, now
  double SnrDb(uint32_t ue, std::size_t u) const;    // its SNR alone
  bool Tcp() const { return scenario.traffic.protocol == "tcp_bulk"; }
  std::string SocketFactory() const {
    return Tcp() ? "ns3::TcpSocketFactory" : "ns3::UdpSocketFactory";
  }
  std::vector<LinkState> LinksTo(std::size_t u) const;
  ns3::NetDeviceContainer InstallWifi(ns3::WifiHelper& wifi);
  void AssignStreams(ns3::WifiHelper& wifi, const ns3::NetDeviceContainer& devices);
  void InstallApplications();
  // UE `ue`'s sink on UAV `u`, installed (and counted as the UE's) on first use.
  void EnsureSink(int u, std::size_t ue);
  // A sender from UE `ue` to its sink on UAV `u`, counted as the UE's; not yet started.
  ns3::Ptr<ns3::Application> InstallSender(std::size_t ue, int u);
  std::vector<std::vector<double>> SnrTable() const;  // [UAV][UE], now
  ns3::Ssid SsidOf(std::size_t u) const { return ns3::Ssid("rlpos-" + scenario.uavs[u].name); }
  void HandOver(std::size_t ue, int to);
  void OnRadioAssociated(std::size_t ue, std::size_t u, ns3::Mac48Address bssid);
  ns3::Ptr<ns3::WifiNetDevice> RadioOf(std::size_t ue, std::size_t u) const {
    return handover ? ue_devices[ue][u] : ue_devices[ue][0];
  }
  void RestartFlow(std::size_t ue);
  ns3::WifiTxVector TxVector(int mcs) const;  // single-user, the configured PHY
};

ns3::WifiTxVector UavNetwork::Impl::TxVector(int mcs) const {
  const WifiSpec& w = scenario.wifi;
  ns3::WifiMode mode;
  ns3::WifiPreamble preamble;
  if (plans[0].standard == ns3::WIFI_STANDARD_80211n) {
    mode = ns3::HtPhy::GetHtMcs(static_cast<uint8_t>(mcs + 8 * (w.spatial_streams - 1)));
    preamble = ns3::WIFI_PREAMBLE_HT_MF;
  } else if (plans[0].standard == ns3::WIFI_STANDARD_80211ac) {
    mode = ns3::VhtPhy::GetVhtMcs(static_cast<uint8_t>(mcs));
    preamble = ns3::WIFI_PREAMBLE_VHT_SU;
  } else {
    mode = ns3::HePhy::GetHeMcs(static_cast<uint8_t>(mcs));
    preamble = ns3::WIFI_PREAMBLE_HE_SU;
  }
  const auto nss = static_cast<uint8_t>(w.spatial_streams);
  return ns3::WifiTxVector(mode, 0, preamble, static_cast<uint16_t>(w.guard_interval_ns), nss, nss,
                           0, static_cast<uint16_t>(w.width_mhz), true);
}

void UavNetwork::Impl::BuildChannelModels() {
  std::set<const ns3::Object*> user_frequency;
  loss = CreateFromSpec(scenario.propagation, "/propagation",
                        ns3::PropagationLossModel::GetTypeId(), "Frequency", &user_frequency)
             ->GetObject<ns3::PropagationLossModel>();
  // Loss models default to their own frequency (ITU-R P.1411: 2.4 GHz): align them with the
  // channel unless the scenario chose one. One model serves every UAV's channel: the first UAV's
  // frequency (two 5 GHz channels differ by well under 1 dB of path loss).
  SetAttributeInTree(loss, "Frequency", ns3::DoubleValue(plans[0].center_frequency_hz),
                     user_frequency);
  geometry = ns3::CreateObject<ns3::BuildingsChannelConditionModel>();
}

ns3::NetDeviceContainer UavNetwork::Impl::InstallWifi(ns3::WifiHelper& wifi) {
  const WifiSpec& w = scenario.wifi;
  // Validates the rate manager spec (type, attributes) before ns-3 would abort on it.
  CreateFromSpec(w.rate_manager, "/wifi/rate_manager", ns3::WifiRemoteStationManager::GetTypeId());

  // One Yans channel per channel number: the BSSs of UAVs on the same channel hear (and
  // interfere with) each other, those on distinct channels do not (no adjacent-channel leakage).
  std::map<int, ns3::Ptr<ns3::YansWifiChannel>> air;
  for (int number : channels) {
    if (air.count(number))
      continue;
    auto channel = ns3::CreateObject<ns3::YansWifiChannel>();
    channel->SetPropagationLossModel(loss);
    channel->SetPropagationDelayModel(ns3::CreateObject<ns3::ConstantSpeedPropagationDelayModel>());
    air[number] = channel;
  }

  ns3::YansWifiPhyHelper phy;
  phy.Set("TxPowerStart", ns3::DoubleValue(w.tx_power_dbm));
  phy.Set("TxPowerEnd", ns3::DoubleValue(w.tx_power_dbm));
  phy.Set("TxGain", ns3::DoubleValue(w.antenna_gain_dbi));
  phy.Set("RxGain", ns3::DoubleValue(w.antenna_gain_dbi));
  phy.Set("RxNoiseFigure", ns3::DoubleValue(plans[0].rx_noise_figure_db));
  phy.Set("Antennas", ns3::UintegerValue(w.spatial_streams));
  phy.Set("MaxSupportedTxSpatialStreams", ns3::UintegerValue(w.spatial_streams));
  phy.Set("MaxSupportedRxSpatialStreams", ns3::UintegerValue(w.spatial_streams));
  phy.SetErrorRateModel(kErrorRateModel);
  // The PHY of a node served by (or being) UAV u: on u's channel.
  auto phy_of = [&](std::size_t u) {
    phy.SetChannel(air[channels[u]]);
    phy.Set("ChannelSettings", ns3::StringValue(plans[u].channel_settings));
    return phy;
  };

  wifi.SetStandard(plans[0].standard);
  wifi.SetRemoteStationManager(w.rate_manager.type);
  if (plans[0].standard == ns3::WIFI_STANDARD_80211ax) {
    wifi.ConfigHeOptions("GuardInterval", ns3::TimeValue(ns3::NanoSeconds(w.guard_interval_ns)));
  } else {
    wifi.ConfigHtOptions("ShortGuardIntervalSupported",
                         ns3::BooleanValue(w.guard_interval_ns == 400));
  }

  // UAVs first, then the UEs, each in the scenario's order (the addresses follow it).
  ns3::WifiMacHelper mac;
  ns3::NetDeviceContainer devices;
  for (std::size_t u = 0; u < scenario.uavs.size(); ++u) {
    if (w.mode == "adhoc") {
      mac.SetType("ns3::AdhocWifiMac");
    } else {
      mac.SetType("ns3::ApWifiMac", "Ssid", ns3::SsidValue(SsidOf(u)));
    }
    devices.Add(wifi.Install(phy_of(u), mac, uavs.Get(static_cast<uint32_t>(u))));
  }
  // Each UE: a radio linked to its serving UAV, or with handover one per UAV (in UAV order).
  ue_devices.assign(ues.GetN(), {});
  for (uint32_t i = 0; i < ues.GetN(); ++i) {
    for (std::size_t u = 0; u < scenario.uavs.size(); ++u) {
      if (!handover && u != static_cast<std::size_t>(serving[i]))
        continue;
      if (w.mode == "adhoc") {
        mac.SetType("ns3::AdhocWifiMac");
      } else if (handover) {
        // The radios stay in their BSS: beacons lost in a saturated shared channel must not
        // drop one (ns-3.37 then flushes a MAC queue with frames in flight, and crashes).
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
  // Rate manager attributes and RTS/CTS are set per instance: Config::SetDefault would leak
  // into every later network built in the same process.
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
  return devices;
}

// Fixed stream numbers for every random variable: ns-3 otherwise numbers streams from a
// process-wide counter, and a second network built in the same process (the gym's episodes, the
// tests) would draw different numbers for the same seed and RngRun.
void UavNetwork::Impl::AssignStreams(ns3::WifiHelper& wifi,
                                     const ns3::NetDeviceContainer& devices) {
  ns3::NodeContainer all(uavs);
  all.Add(ues);
  int64_t stream = 0;
  stream += loss->AssignStreams(stream);
  stream += wifi.AssignStreams(devices, stream);
  ns3::MobilityHelper mobility;
  stream += mobility.AssignStreams(all, stream);
  ns3::InternetStackHelper internet;
  stream += internet.AssignStreams(all, stream);
  for (const auto& sender : senders) {
    if (auto onoff = ns3::DynamicCast<ns3::OnOffApplication>(sender)) {
      stream += onoff->AssignStreams(stream);
    }
  }
}

void UavNetwork::Impl::EnsureSink(int u, std::size_t ue) {
  if (sinks.count({u, ue}))
    return;
  const auto port = static_cast<uint16_t>(kFirstPort + ue);
  ns3::PacketSinkHelper helper(SocketFactory(),
                               ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), port));
  helper.SetAttribute("EnableSeqTsSizeHeader", ns3::BooleanValue(true));
  ns3::Ptr<ns3::Application> sink = helper.Install(uavs.Get(static_cast<uint32_t>(u))).Get(0);
  sink->SetStartTime(ns3::Seconds(0.0));
  sinks[{u, ue}] = sink;
  traffic->AttachSink(ue, sink);
}

ns3::Ptr<ns3::Application> UavNetwork::Impl::InstallSender(std::size_t ue, int u) {
  const bool tcp = Tcp();
  const std::string socket = SocketFactory();
  const ns3::InetSocketAddress to(uav_addresses[static_cast<std::size_t>(u)],
                                  static_cast<uint16_t>(kFirstPort + ue));
  ns3::ApplicationContainer app;
  if (tcp) {
    ns3::BulkSendHelper bulk(socket, to);
    bulk.SetAttribute("SendSize", ns3::UintegerValue(scenario.traffic.packet_size));
    bulk.SetAttribute("MaxBytes", ns3::UintegerValue(0));
    bulk.SetAttribute("EnableSeqTsSizeHeader", ns3::BooleanValue(true));
    app = bulk.Install(ues.Get(static_cast<uint32_t>(ue)));
  } else {
    ns3::OnOffHelper onoff(socket, to);
    onoff.SetConstantRate(ns3::DataRate(static_cast<uint64_t>(scenario.ues[ue].demand_mbps * 1e6)),
                          scenario.traffic.packet_size);
    onoff.SetAttribute("EnableSeqTsSizeHeader", ns3::BooleanValue(true));
    app = onoff.Install(ues.Get(static_cast<uint32_t>(ue)));
  }
  traffic->AttachSender(ue, app.Get(0));
  return app.Get(0);
}

void UavNetwork::Impl::InstallApplications() {
  const double duration = scenario.simulation.duration;
  // Staggered starts (drawn from the run's RNG) so that UEs do not contend in lockstep.
  start_times = ns3::CreateObject<ns3::UniformRandomVariable>();
  start_times->SetAttribute("Min", ns3::DoubleValue(0.05));
  start_times->SetAttribute("Max", ns3::DoubleValue(0.15));
  start_times->SetStream(kStartTimesStream);  // drawn now, before AssignStreams runs
  for (std::size_t i = 0; i < scenario.ues.size(); ++i) {
    // The UE's flow ends at its serving UAV.
    EnsureSink(serving[i], i);
    ns3::Ptr<ns3::Application> app = InstallSender(i, serving[i]);
    app->SetStartTime(ns3::Seconds(start_times->GetValue()));
    app->SetStopTime(ns3::Seconds(duration));
    senders.push_back(app);
  }
}

std::vector<std::vector<double>> UavNetwork::Impl::SnrTable() const {
  // SNR only: the association needs no LoS (a building ray test per link).
  std::vector<std::vector<double>> snr(uavs.GetN());
  for (std::size_t u = 0; u < snr.size(); ++u) {
    for (uint32_t i = 0; i < ues.GetN(); ++i)
      snr[u].push_back(SnrDb(i, u));
  }
  return snr;
}

namespace {

// Stops a sender now, for good: ns-3 applications have no public stop once started, so its
// socket loses the callbacks into it and is closed, and the application is disposed.
void StopSender(const ns3::Ptr<ns3::Application>& app) {
  ns3::Ptr<ns3::Socket> socket;
  if (auto onoff = ns3::DynamicCast<ns3::OnOffApplication>(app))
    socket = onoff->GetSocket();
  else if (auto bulk = ns3::DynamicCast<ns3::BulkSendApplication>(app))
    socket = bulk->GetSocket();
  if (socket) {
    socket->SetConnectCallback(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>(),
                               ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>());
    socket->SetCloseCallbacks(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>(),
                              ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>());
    socket->SetSendCallback(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>, uint32_t>());
    socket->SetDataSentCallback(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>, uint32_t>());
    socket->SetRecvCallback(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>());
    socket->Close();
  }
  app->Dispose();  // cancels its pending start, stop and send events
}

}  // namespace

// The handover: the UE's flow to its old UAV stops, and restarts from its radio in the new UAV's
// BSS to a sink on that UAV (UDP: from the next packet; TCP: a new connection) as soon as that
// radio is associated: at once if it already is, else when ns-3's STA has heard the AP and
// completed the handshake (OnRadioAssociated), so that nothing is sent into a BSS not joined.
void UavNetwork::Impl::HandOver(std::size_t ue, int to) {
  serving[ue] = to;
  ++handovers;
  StopSender(senders[ue]);
  auto sta = ns3::DynamicCast<ns3::StaWifiMac>(RadioOf(ue, static_cast<std::size_t>(to))->GetMac());
  joining[ue] = sta && !sta->IsAssociated();
  if (!joining[ue])
    RestartFlow(ue);
}

void UavNetwork::Impl::OnRadioAssociated(std::size_t ue, std::size_t u, ns3::Mac48Address) {
  if (joining[ue] && static_cast<std::size_t>(serving[ue]) == u) {
    joining[ue] = false;
    RestartFlow(ue);
  }
}

void UavNetwork::Impl::RestartFlow(std::size_t ue) {
  const double left = scenario.simulation.duration - ns3::Simulator::Now().GetSeconds();
  if (left <= 0.0)
    return;  // traffic is over
  EnsureSink(serving[ue], ue);
  ns3::Ptr<ns3::Application> app = InstallSender(ue, serving[ue]);
  if (auto onoff = ns3::DynamicCast<ns3::OnOffApplication>(app)) {
    handover_streams += onoff->AssignStreams(handover_streams);
  }
  // Both relative to now: the application is initialized when added to its node.
  app->SetStartTime(ns3::Seconds(0.0));
  app->SetStopTime(ns3::Seconds(left));
  senders[ue] = app;
}

UavNetwork::UavNetwork(const Scenario& scenario, const Placement& placement, Handover handover)
    : impl_(std::make_unique<Impl>()) {
  if (placement.size() != scenario.uavs.size()) {
    throw std::invalid_argument(std::to_string(placement.size()) + " positions for " +
                                std::to_string(scenario.uavs.size()) + " UAVs");
  }
  Impl& m = *impl_;
  m.scenario = scenario;
  m.handover = handover == Handover::kOn;
  ns3::Simulator::Destroy();  // a clean slate: node and building lists are global
  ns3::RngSeedManager::SetSeed(scenario.simulation.seed);
  ns3::RngSeedManager::SetRun(scenario.simulation.run);

  m.plans = PlanUavChannels(scenario);
  for (const auto& plan : m.plans)
    m.channels.push_back(plan.channel);
  m.BuildChannelModels();
  m.error_model = ns3::ObjectFactory(kErrorRateModel).Create<ns3::ErrorRateModel>();
  BuildBuildings(scenario);

  m.ues.Create(scenario.ues.size());
  m.uavs.Create(static_cast<uint32_t>(scenario.uavs.size()));
  InstallUeMobility(scenario, m.ues);
  ns3::MobilityHelper uav_mobility;
  uav_mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
  uav_mobility.Install(m.uavs);
  for (std::size_t u = 0; u < placement.size(); ++u) {
    m.UavMobility(u)->SetPosition(ToNs3(placement[u]));
  }
  ns3::BuildingsHelper::Install(m.ues);
  ns3::BuildingsHelper::Install(m.uavs);

  m.serving = AssociateUes(scenario, m.SnrTable());

  ns3::WifiHelper wifi;
  ns3::NetDeviceContainer devices = m.InstallWifi(wifi);
  ns3::InternetStackHelper internet;
  internet.Install(m.uavs);
  internet.Install(m.ues);
  for (uint32_t u = 0; u < m.uavs.GetN(); ++u)
    m.uav_devices.push_back(ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(u)));
  ns3::Ipv4AddressHelper addresses;
  if (!m.handover) {
    // One subnet, UAVs first: 10.1.0.1, 10.1.0.2, ..., then the UEs.
    addresses.SetBase("10.1.0.0", "255.255.0.0");
    ns3::Ipv4InterfaceContainer interfaces = addresses.Assign(devices);
    for (uint32_t u = 0; u < m.uavs.GetN(); ++u)
      m.uav_addresses.push_back(interfaces.GetAddress(u));
  } else {
    // A subnet per UAV, 10.<u+1>.0.0/16: its AP (.0.1) and every UE's radio linked to it, so that
    // a flow to UAV u leaves the UE by that radio.
    for (std::size_t u = 0; u < m.uav_devices.size(); ++u) {
      ns3::NetDeviceContainer subnet(m.uav_devices[u]);
      for (const auto& radios : m.ue_devices)
        subnet.Add(radios[u]);
      addresses.SetBase(ns3::Ipv4Address(("10." + std::to_string(u + 1) + ".0.0").c_str()),
                        "255.255.0.0");
      m.uav_addresses.push_back(addresses.Assign(subnet).GetAddress(0));
    }
  }
  if (scenario.wifi.mode == "adhoc") {
    // No ARP on the air: in ad hoc mode unacknowledged broadcast ARP requests collide under
    // saturated load and starve UEs for seconds. (AP/STA association sorts itself out.)
    ns3::NeighborCacheHelper().PopulateNeighborCache();
  }
  m.joining.assign(scenario.ues.size(), false);
  for (std::size_t i = 0; m.handover && i < m.ue_devices.size(); ++i) {
    for (std::size_t u = 0; u < m.ue_devices[i].size(); ++u) {
      m.ue_devices[i][u]->GetMac()->TraceConnectWithoutContext(
          "Assoc", ns3::MakeCallback(&Impl::OnRadioAssociated, &m).Bind(i, u));
    }
  }
  m.traffic = std::make_unique<TrafficMonitor>(scenario.ues.size());
  m.InstallApplications();
  m.AssignStreams(wifi, devices);
}

UavNetwork::~UavNetwork() {
  impl_->traffic.reset();
  ns3::Simulator::Destroy();
}

const Scenario& UavNetwork::scenario() const {
  return impl_->scenario;
}

void UavNetwork::SetUavPositions(const Placement& placement) {
  if (placement.size() != impl_->uavs.GetN())
    throw std::invalid_argument("a placement of another size than the UAVs");
  for (std::size_t u = 0; u < placement.size(); ++u)
    impl_->UavMobility(u)->SetPosition(ToNs3(placement[u]));
}

void UavNetwork::SetUavPosition(std::size_t uav, const Vec3& position) {
  if (uav >= impl_->uavs.GetN())
    throw std::out_of_range("no UAV " + std::to_string(uav));
  impl_->UavMobility(uav)->SetPosition(ToNs3(position));
}

Placement UavNetwork::UavPositions() const {
  Placement placement;
  for (uint32_t u = 0; u < impl_->uavs.GetN(); ++u)
    placement.push_back(FromNs3(impl_->UavMobility(u)->GetPosition()));
  return placement;
}

int UavNetwork::Reassociate() {
  Impl& m = *impl_;
  if (!m.handover)
    throw std::logic_error("this network was built without handover");
  const std::vector<int> serving = AssociateUes(m.scenario, m.SnrTable());
  int changed = 0;
  for (std::size_t i = 0; i < serving.size(); ++i) {
    if (serving[i] != m.serving[i]) {
      m.HandOver(i, serving[i]);
      ++changed;
    }
  }
  return changed;
}

std::size_t UavNetwork::Handovers() const {
  return impl_->handovers;
}

std::vector<int> UavNetwork::AssociatedAps() const {
  const Impl& m = *impl_;
  std::vector<int> aps(m.ue_devices.size(), -1);
  for (std::size_t i = 0; i < aps.size(); ++i) {
    const auto u = static_cast<std::size_t>(m.serving[i]);
    auto sta = ns3::DynamicCast<ns3::StaWifiMac>(m.RadioOf(i, u)->GetMac());
    if (sta && sta->IsAssociated() && sta->GetBssid(0) == m.uav_devices[u]->GetMac()->GetAddress())
      aps[i] = static_cast<int>(u);
  }
  return aps;
}

const std::vector<int>& UavNetwork::Association() const {
  return impl_->serving;
}

std::vector<int> UavNetwork::UavChannels() const {
  return impl_->channels;
}

LinkState UavNetwork::Impl::Link(uint32_t i, std::size_t u) const {
  auto uav = UavMobility(u);
  auto ue = ues.Get(i)->GetObject<ns3::MobilityModel>();
  LinkState link;
  link.los = geometry->GetChannelCondition(ue, uav)->IsLos();
  link.snr_db = SnrDb(i, u);
  return link;
}

double UavNetwork::Impl::SnrDb(uint32_t i, std::size_t u) const {
  const WifiSpec& w = scenario.wifi;
  // Uplink, as the channel computes it: sender first.
  const double rx_dbm =
      loss->CalcRxPower(w.tx_power_dbm + w.antenna_gain_dbi,
                        ues.Get(i)->GetObject<ns3::MobilityModel>(), UavMobility(u)) +
      w.antenna_gain_dbi;
  return rx_dbm - w.noise_floor_dbm;
}

std::vector<LinkState> UavNetwork::Impl::LinksTo(std::size_t u) const {
  std::vector<LinkState> links;
  links.reserve(ues.GetN());
  for (uint32_t i = 0; i < ues.GetN(); ++i)
    links.push_back(Link(i, u));
  return links;
}

std::vector<LinkState> UavNetwork::LinksTo(std::size_t uav) const {
  if (uav >= impl_->uavs.GetN())
    throw std::out_of_range("no UAV " + std::to_string(uav));
  return impl_->LinksTo(uav);
}

std::vector<LinkState> UavNetwork::Links() const {
  const Impl& m = *impl_;
  std::vector<LinkState> links;
  links.reserve(m.ues.GetN());
  for (uint32_t i = 0; i < m.ues.GetN(); ++i)
    links.push_back(m.Link(i, static_cast<std::size_t>(m.serving[i])));
  return links;
}

std::vector<double> UavNetwork::McsSnrThresholdsDb() const {
  const Impl& m = *impl_;
  const WifiSpec& w = m.scenario.wifi;
  double ber = 1e-6;  // IdealWifiManager's default BerThreshold
  auto manager = m.uav_devices[0]->GetRemoteStationManager();
  ns3::TypeId::AttributeInformation info;
  if (manager->GetInstanceTypeId().LookupAttributeByName("BerThreshold", &info)) {
    ns3::DoubleValue value;
    manager->GetAttribute("BerThreshold", value);
    ber = value.Get();
  }
  auto phy = m.uav_devices[0]->GetPhy();
  std::vector<double> thresholds;
  for (int mcs = 0; mcs <= MaxMcs(w.standard); ++mcs) {
    thresholds.push_back(10.0 * std::log10(phy->CalculateSnr(m.TxVector(mcs), ber)));
  }
  return thresholds;
}

double UavNetwork::MpduSuccessRate(int mcs, double snr_db, int mpdu_bytes) const {
  const ns3::WifiTxVector tx = impl_->TxVector(mcs);
  return impl_->error_model->GetChunkSuccessRate(tx.GetMode(), tx, std::pow(10.0, snr_db / 10),
                                                 static_cast<uint64_t>(mpdu_bytes) * 8,
                                                 tx.GetNss());
}

void UavNetwork::BeginMeasurement(MeasurementWindow window) {
  impl_->traffic->Restart(window);
}

void UavNetwork::RunUntil(double t) {
  const ns3::Time target = ns3::Seconds(t);
  if (target <= ns3::Simulator::Now())
    return;
  ns3::Simulator::Stop(target - ns3::Simulator::Now());
  ns3::Simulator::Run();
}

double UavNetwork::Now() const {
  return ns3::Simulator::Now().GetSeconds();
}

RunMetrics UavNetwork::Measure() const {
  const Impl& m = *impl_;
  const PhyProfile phy{m.scenario.wifi.standard, m.scenario.wifi.width_mhz,
                       m.scenario.wifi.guard_interval_ns, m.scenario.wifi.spatial_streams};
  const auto links = Links();
  std::vector<UeMetrics> ues(links.size());
  for (std::size_t i = 0; i < links.size(); ++i) {
    ues[i].name = m.scenario.ues[i].name;
    ues[i].uav = m.serving[i];
    ues[i].los = links[i].los;
    ues[i].snr_db = links[i].snr_db;
    ues[i].demand_mbps = m.scenario.ues[i].demand_mbps;
    ues[i].demand = CheckDemand(phy, ues[i].demand_mbps, links[i].snr_db);
  }
  const Placement placement = UavPositions();
  std::vector<UavIdentity> uavs;
  for (std::size_t u = 0; u < placement.size(); ++u)
    uavs.push_back({m.scenario.uavs[u].name, placement[u], m.channels[u]});
  return Summarize(uavs, m.traffic->window(), m.scenario.simulation.run, m.traffic->flows(),
                   std::move(ues));
}

RunMetrics EvaluatePosition(const Scenario& scenario, const Placement& placement,
                            void (*on_progress)(double now, double end)) {
  UavNetwork network(scenario, placement);
  const double end = scenario.simulation.duration;
  network.BeginMeasurement({scenario.simulation.warmup, end});
  // Packets still queued when traffic stops are delivered within the MAC queue's lifetime.
  const double drain = 0.5;
  const int slices = on_progress ? 20 : 1;
  for (int k = 1; k <= slices; ++k) {
    network.RunUntil(end * k / slices);
    if (on_progress)
      on_progress(network.Now(), end);
  }
  network.RunUntil(end + drain);
  return network.Measure();
}

}  // namespace rlpos
