// A hand-written ns-3 program of the same setup rlpos-sim eval builds (buildings, Wi-Fi, UDP CBR
// to a sink on the UAV), with no RLpos scenario builder, validation or monitors: the reference
// for the framework-overhead benchmark (scripts/bench_eval_overhead.sh). It reads the scenario
// JSON without validating it and loads the loss model by TypeId name, as any ns-3 program could.
//   rlpos-bare-ns3 SCENARIO.json x y z DURATION
#include <ns3/applications-module.h>
#include <ns3/buildings-module.h>
#include <ns3/core-module.h>
#include <ns3/internet-module.h>
#include <ns3/mobility-module.h>
#include <ns3/network-module.h>
#include <ns3/propagation-module.h>
#include <ns3/wifi-module.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "tests/support/program_usage.h"
#include "worker/env/network/obstacle_aware_propagation_loss_model.h"

using namespace ns3;
using nlohmann::json;

namespace {

Ptr<Object> Make(const json& spec, double frequency) {
  ObjectFactory factory(spec.at("type").get<std::string>());
  const json attributes = spec.value("attributes", json::object());
  for (const auto& [name, value] : attributes.items()) {
    if (value.is_object()) {
      factory.Set(name, PointerValue(Make(value, frequency)));
    } else {
      factory.Set(name, StringValue(value.is_string() ? value.get<std::string>() : value.dump()));
    }
  }
  Ptr<Object> object = factory.Create();
  TypeId::AttributeInformation info;
  if (object->GetInstanceTypeId().LookupAttributeByName("Frequency", &info)) {
    object->SetAttribute("Frequency", DoubleValue(frequency));
  }
  return object;
}

void AddBuildings(const json& s) {
  for (const auto& b : s.value("buildings", json::array())) {
    auto building = CreateObject<Building>();
    building->SetBoundaries(Box(b["x"][0], b["x"][1], b["y"][0], b["y"][1], 0, b["height"]));
  }
}

// The UAV and the UEs at their places, in the buildings' model.
void PlaceNodes(const json& s, const Vector& uav_position, Ptr<Node> uav, NodeContainer& ues,
                MobilityHelper& mobility) {
  mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
  mobility.Install(uav);
  mobility.Install(ues);
  uav->GetObject<MobilityModel>()->SetPosition(uav_position);
  for (uint32_t i = 0; i < ues.GetN(); ++i) {
    const auto& p = s["ues"][i]["position"];
    ues.Get(i)->GetObject<MobilityModel>()->SetPosition(Vector(p[0], p[1], p[2]));
  }
  BuildingsHelper::Install(ues);
  BuildingsHelper::Install(NodeContainer(uav));
}

Ptr<YansWifiChannel> MakeChannel(Ptr<PropagationLossModel> loss) {
  auto channel = CreateObject<YansWifiChannel>();
  channel->SetPropagationLossModel(loss);
  channel->SetPropagationDelayModel(CreateObject<ConstantSpeedPropagationDelayModel>());
  return channel;
}

void ConfigurePhy(const json& w, Ptr<YansWifiChannel> channel, YansWifiPhyHelper& phy) {
  phy.SetChannel(channel);
  phy.Set("ChannelSettings", StringValue("{50, 160, BAND_5GHZ, 0}"));
  phy.Set("TxPowerStart", DoubleValue(w["tx_power"]));
  phy.Set("TxPowerEnd", DoubleValue(w["tx_power"]));
  phy.Set("TxGain", DoubleValue(w["antenna_gain"]));
  phy.Set("RxGain", DoubleValue(w["antenna_gain"]));
  phy.Set("RxNoiseFigure",
          DoubleValue(w["noise_floor"].get<double>() + 174.0 - 10 * std::log10(160e6)));
}

// The UAV as the access point, the UEs as its stations: the UAV's device first.
NetDeviceContainer InstallWifi(const json& w, Ptr<PropagationLossModel> loss, Ptr<Node> uav,
                               const NodeContainer& ues, WifiHelper& wifi) {
  const Ptr<YansWifiChannel> channel = MakeChannel(loss);
  YansWifiPhyHelper phy;
  ConfigurePhy(w, channel, phy);
  wifi.SetStandard(WIFI_STANDARD_80211ac);
  wifi.SetRemoteStationManager("ns3::IdealWifiManager");
  WifiMacHelper mac;
  const Ssid ssid("rlpos-uav");
  mac.SetType("ns3::ApWifiMac", "Ssid", SsidValue(ssid));
  NetDeviceContainer devices = wifi.Install(phy, mac, uav);
  mac.SetType("ns3::StaWifiMac", "Ssid", SsidValue(ssid));
  devices.Add(wifi.Install(phy, mac, ues));
  return devices;
}

// The UAV's address.
Ipv4Address InstallInternet(const NetDeviceContainer& devices, Ptr<Node> uav,
                            const NodeContainer& ues, InternetStackHelper& internet) {
  internet.Install(uav);
  internet.Install(ues);
  Ipv4AddressHelper addresses;
  addresses.SetBase("10.1.0.0", "255.255.0.0");
  return addresses.Assign(devices).GetAddress(0);
}

// A UDP CBR sender on each UE, at its demand, to a sink of its own on the UAV.
void InstallTraffic(const json& s, const NodeContainer& ues, Ptr<Node> uav,
                    const Ipv4Address& uav_address, double duration, ApplicationContainer& sinks,
                    ApplicationContainer& senders) {
  // Same start times and stream numbers as rlpos-sim, so both simulate the same events.
  auto start_times = CreateObject<UniformRandomVariable>();
  start_times->SetAttribute("Min", DoubleValue(0.05));
  start_times->SetAttribute("Max", DoubleValue(0.15));
  start_times->SetStream(1000000);
  for (uint32_t i = 0; i < ues.GetN(); ++i) {
    const uint16_t port = 9000 + i;
    PacketSinkHelper sink("ns3::UdpSocketFactory", InetSocketAddress(Ipv4Address::GetAny(), port));
    sink.SetAttribute("EnableSeqTsSizeHeader", BooleanValue(true));
    sinks.Add(sink.Install(uav));
    OnOffHelper onoff("ns3::UdpSocketFactory", InetSocketAddress(uav_address, port));
    const json& demand = s["ues"][i]["demand"];
    const double mbps = demand.contains("mbps") ? demand["mbps"].get<double>()
                                                : 58.5 * (demand["mcs"].get<int>() + 1);
    onoff.SetConstantRate(DataRate(static_cast<uint64_t>(mbps * 1e6)), 1400);
    onoff.SetAttribute("EnableSeqTsSizeHeader", BooleanValue(true));
    ApplicationContainer app = onoff.Install(ues.Get(i));
    app.Start(Seconds(start_times->GetValue()));
    senders.Add(app);
    app.Stop(Seconds(duration));
  }
}

}  // namespace

int main(int argc, char** argv) {
  constexpr char kUsage[] = "usage: rlpos-bare-ns3 SCENARIO.json x y z DURATION\n";
  if (rlpos::testing::PrintedHelp(argc, argv, kUsage))
    return 0;
  if (argc != 6)
    return rlpos::testing::UsageError(kUsage);
  // Referencing the model keeps its library linked (and its TypeId registered).
  ObstacleAwarePropagationLossModel::GetTypeId();
  json s;
  std::ifstream(argv[1]) >> s;
  const Vector uav_position(std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]));
  const double duration = std::atof(argv[5]);
  const json& sim = s.at("simulation");
  RngSeedManager::SetSeed(sim.at("seed").get<uint32_t>());
  RngSeedManager::SetRun(sim.at("run").get<uint64_t>());

  // Made in rlpos-sim's order (buildings, the UEs, then the UAV), for the same node ids.
  AddBuildings(s);
  NodeContainer ues(s.at("ues").size());
  Ptr<Node> uav = CreateObject<Node>();
  MobilityHelper mobility;
  PlaceNodes(s, uav_position, uav, ues, mobility);
  const json& w = s.at("wifi");
  auto loss = Make(s.at("propagation"), 5250e6)->GetObject<PropagationLossModel>();
  WifiHelper wifi;
  NetDeviceContainer devices = InstallWifi(w, loss, uav, ues, wifi);
  InternetStackHelper internet;
  const Ipv4Address uav_address = InstallInternet(devices, uav, ues, internet);
  ApplicationContainer sinks, senders;
  InstallTraffic(s, ues, uav, uav_address, duration, sinks, senders);

  NodeContainer all(uav);
  all.Add(ues);
  int64_t stream = loss->AssignStreams(0);
  stream += wifi.AssignStreams(devices, stream);
  stream += mobility.AssignStreams(all, stream);
  stream += internet.AssignStreams(all, stream);
  for (uint32_t i = 0; i < senders.GetN(); ++i) {
    stream += DynamicCast<OnOffApplication>(senders.Get(i))->AssignStreams(stream);
  }
  Simulator::Stop(Seconds(duration + 0.5));
  Simulator::Run();
  uint64_t bytes = 0;
  for (uint32_t i = 0; i < sinks.GetN(); ++i)
    bytes += DynamicCast<PacketSink>(sinks.Get(i))->GetTotalRx();
  std::cout << "received " << bytes << " bytes in the whole run\n";
  Simulator::Destroy();
  return 0;
}
