// The UAV network: the channel models, the buildings, the nodes and their addresses, and the
// links as the channel sees them. The radios, the flows and the handover are in the
// uav_network_*.cc files beside it.
#include "worker/env/network/uav_network.h"

#include <ns3/buildings-helper.h>
#include <ns3/core-module.h>
#include <ns3/double.h>
#include <ns3/error-rate-model.h>
#include <ns3/internet-stack-helper.h>
#include <ns3/ipv4-address-helper.h>
#include <ns3/mobility-helper.h>
#include <ns3/neighbor-cache-helper.h>
#include <ns3/onoff-application.h>
#include <ns3/waypoint-mobility-model.h>
#include <ns3/wifi-phy.h>
#include <ns3/wifi-remote-station-manager.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "common/scenario/building_obstacles.h"
#include "worker/env/network/association.h"
#include "worker/env/network/loss_model_spec.h"
#include "worker/env/network/ns3_object_spec.h"
#include "worker/env/network/uav_network_impl.h"
#include "worker/env/network/ue_mobility.h"
#include "worker/env/network/venue_obstacles.h"

namespace rlpos {
namespace {

std::atomic<bool>& NetworkAlive() {
  static std::atomic<bool> alive{false};
  return alive;
}

}  // namespace

OneNetworkPerProcess::OneNetworkPerProcess() {
  if (NetworkAlive().exchange(true)) {
    throw std::runtime_error(
        "a second packet-level ns-3 network in this process: ns-3's simulator and building list "
        "are process-wide, so a process holds one packet-level env or evaluation at a time; run "
        "each in a process of its own (the analytic fidelity has no such limit)");
  }
}

OneNetworkPerProcess::~OneNetworkPerProcess() {
  NetworkAlive() = false;
}

void UavNetwork::Impl::BuildChannelModels() {
  // One model serves every UAV's channel: the first UAV's frequency (two 5 GHz channels differ
  // by well under 1 dB of path loss).
  loss = CreateLossModel(scenario, plans[0].center_frequency_hz);
  auto obstacles = std::make_shared<const Obstacles>(BuildingObstacles(scenario.buildings));
  GiveObstacles(scenario, loss, obstacles, "/propagation");
  geometry = ns3::CreateObject<ns3::ObstaclesChannelConditionModel>();
  geometry->SetObstacles(obstacles);
}

void UavNetwork::Impl::BuildNodes(const Placement& placement) {
  ues.Create(scenario.ues.size());
  uavs.Create(static_cast<uint32_t>(scenario.uavs.size()));
  InstallUeMobility(scenario, ues);
  ns3::MobilityHelper uav_mobility;
  if (!uavs_fly) {
    uav_mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
    uav_mobility.Install(uavs);
    for (std::size_t u = 0; u < placement.size(); ++u)
      UavMobility(u)->SetPosition(ToNs3(placement[u]));
  } else {
    // The first waypoint is where the UAV holds until the next one that FlyUav adds.
    uav_mobility.SetMobilityModel("ns3::WaypointMobilityModel");
    uav_mobility.Install(uavs);
    for (std::size_t u = 0; u < placement.size(); ++u) {
      uavs.Get(static_cast<uint32_t>(u))
          ->GetObject<ns3::WaypointMobilityModel>()
          ->AddWaypoint(ns3::Waypoint(ns3::Seconds(0), ToNs3(placement[u])));
    }
    last_waypoint_ns.assign(placement.size(), 0);
  }
  ns3::BuildingsHelper::Install(ues);
  ns3::BuildingsHelper::Install(uavs);
}

void UavNetwork::Impl::InstallInternet(const ns3::NetDeviceContainer& devices) {
  ns3::InternetStackHelper internet;
  internet.Install(uavs);
  internet.Install(ues);
  for (uint32_t u = 0; u < uavs.GetN(); ++u)
    uav_devices.push_back(ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(u)));
  ns3::Ipv4AddressHelper addresses;
  if (!handover) {
    // One subnet, UAVs first: 10.1.0.1, 10.1.0.2, ..., then the UEs.
    addresses.SetBase("10.1.0.0", "255.255.0.0");
    ns3::Ipv4InterfaceContainer interfaces = addresses.Assign(devices);
    for (uint32_t u = 0; u < uavs.GetN(); ++u)
      uav_addresses.push_back(interfaces.GetAddress(u));
  } else {
    // A subnet per UAV, 10.<u+1>.0.0/16: its AP (.0.1) and every UE's radio linked to it, so that
    // a flow to UAV u leaves the UE by that radio.
    for (std::size_t u = 0; u < uav_devices.size(); ++u) {
      ns3::NetDeviceContainer subnet(uav_devices[u]);
      for (const auto& radios : ue_devices)
        subnet.Add(radios[u]);
      addresses.SetBase(ns3::Ipv4Address(("10." + std::to_string(u + 1) + ".0.0").c_str()),
                        "255.255.0.0");
      uav_addresses.push_back(addresses.Assign(subnet).GetAddress(0));
    }
  }
  if (scenario.wifi.mode == "adhoc") {
    // No ARP on the air: in ad hoc mode unacknowledged broadcast ARP requests collide under
    // saturated load and starve UEs for seconds. (AP/STA association sorts itself out.)
    ns3::NeighborCacheHelper().PopulateNeighborCache();
  }
}

UavNetwork::UavNetwork(const Scenario& scenario, const Placement& placement, Handover handover,
                       UavMotion motion)
    : impl_(std::make_unique<Impl>()) {
  if (placement.size() != scenario.uavs.size()) {
    throw std::invalid_argument(std::to_string(placement.size()) + " positions for " +
                                std::to_string(scenario.uavs.size()) + " UAVs");
  }
  Impl& m = *impl_;
  m.scenario = scenario;
  m.handover = handover == Handover::kOn;
  m.uavs_fly = motion == UavMotion::kFlies;
  ns3::Simulator::Destroy();  // a clean slate: node and building lists are global
  ns3::RngSeedManager::SetSeed(scenario.simulation.seed);
  ns3::RngSeedManager::SetRun(scenario.simulation.run);

  // From here on, order matters: a random variable that AssignStreams does not reach takes its
  // stream from ns-3's counter, in the order it is made.
  m.plans = PlanUavChannels(scenario);
  for (const auto& plan : m.plans)
    m.channels.push_back(plan.channel);
  m.BuildChannelModels();
  m.error_model = ns3::ObjectFactory(kErrorRateModel).Create<ns3::ErrorRateModel>();
  BuildNs3Buildings(scenario);
  m.BuildNodes(placement);
  m.serving = AssociateUes(scenario, m.SnrTable());
  ns3::WifiHelper wifi;
  ns3::NetDeviceContainer devices = m.InstallWifi(wifi);
  m.InstallInternet(devices);
  m.joining.assign(scenario.ues.size(), false);
  m.ConnectAssociationTraces();
  m.traffic = std::make_unique<TrafficMonitor>(scenario.ues.size());
  m.InstallApplications();
  m.AssignStreams(wifi, devices);
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

std::vector<std::vector<double>> UavNetwork::Impl::SnrTable() const {
  // SNR only: the association needs no LoS (a building ray test per link).
  std::vector<std::vector<double>> snr(uavs.GetN());
  for (std::size_t u = 0; u < snr.size(); ++u) {
    for (uint32_t i = 0; i < ues.GetN(); ++i)
      snr[u].push_back(SnrDb(i, u));
  }
  return snr;
}

UavNetwork::~UavNetwork() {
  impl_->traffic.reset();
  ns3::Simulator::Destroy();
}

const Scenario& UavNetwork::scenario() const {
  return impl_->scenario;
}

void UavNetwork::SetUavPositions(const Placement& placement) {
  if (impl_->uavs_fly)
    throw std::logic_error("SetUavPositions on a network whose UAVs fly: use FlyUav");
  if (placement.size() != impl_->uavs.GetN())
    throw std::invalid_argument("a placement of another size than the UAVs");
  for (std::size_t u = 0; u < placement.size(); ++u)
    impl_->UavMobility(u)->SetPosition(ToNs3(placement[u]));
}

void UavNetwork::SetUavPosition(std::size_t uav, const Vec3& position) {
  if (uav >= impl_->uavs.GetN())
    throw std::out_of_range("no UAV " + std::to_string(uav));
  if (impl_->uavs_fly)
    throw std::logic_error("SetUavPosition on a network whose UAVs fly: use FlyUav");
  impl_->UavMobility(uav)->SetPosition(ToNs3(position));
}

void UavNetwork::FlyUav(std::size_t uav, const Vec3& to, double arrive_at) {
  Impl& m = *impl_;
  if (uav >= m.uavs.GetN())
    throw std::out_of_range("no UAV " + std::to_string(uav));
  if (!m.uavs_fly)
    throw std::logic_error("FlyUav on a network built with UavMotion::kFixed");
  const int64_t now = ns3::Simulator::Now().GetNanoSeconds();
  const int64_t arrive = std::llround(arrive_at * 1e9);
  if (arrive <= now) {
    throw std::invalid_argument("FlyUav: an arrival at " + std::to_string(arrive_at) +
                                " s, not after now");
  }
  if (arrive <= m.last_waypoint_ns[uav]) {
    throw std::logic_error("FlyUav: UAV " + std::to_string(uav) +
                           " arrives before the end of its last leg");
  }
  auto mobility = m.uavs.Get(static_cast<uint32_t>(uav))->GetObject<ns3::WaypointMobilityModel>();
  const ns3::Vector from = mobility->GetPosition();  // consumes the waypoints up to now
  if (from.x == to.x && from.y == to.y && from.z == to.z)
    return;  // after its last waypoint the model holds the UAV where it is
  // A waypoint now, where the UAV is: past its last waypoint the model dates its position at
  // -1 s, and would spread the next leg from then on. A leg given before the last one ends
  // starts where that one ends.
  if (m.last_waypoint_ns[uav] <= now)
    mobility->AddWaypoint(ns3::Waypoint(ns3::NanoSeconds(now), from));
  mobility->AddWaypoint(ns3::Waypoint(ns3::NanoSeconds(arrive), ToNs3(to)));
  m.last_waypoint_ns[uav] = arrive;
}

Placement UavNetwork::UavPositions() const {
  Placement placement;
  for (uint32_t u = 0; u < impl_->uavs.GetN(); ++u)
    placement.push_back(FromNs3(impl_->UavMobility(u)->GetPosition()));
  return placement;
}

std::vector<Vec3> UavNetwork::UePositions() const {
  std::vector<Vec3> positions;
  for (uint32_t i = 0; i < impl_->ues.GetN(); ++i)
    positions.push_back(FromNs3(impl_->ues.Get(i)->GetObject<ns3::MobilityModel>()->GetPosition()));
  return positions;
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