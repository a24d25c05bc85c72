// The UEs' flows: each UE sends to a sink on its serving UAV (UDP at its demand, or TCP bulk),
// starting at a staggered time, counted by the traffic monitor.
#include <ns3/boolean.h>
#include <ns3/bulk-send-helper.h>
#include <ns3/double.h>
#include <ns3/inet-socket-address.h>
#include <ns3/on-off-helper.h>
#include <ns3/packet-sink-helper.h>
#include <ns3/uinteger.h>

#include "worker/env/network/uav_network_impl.h"

namespace rlpos {

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

}  // namespace rlpos
