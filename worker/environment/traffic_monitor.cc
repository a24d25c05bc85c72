#include "environment/traffic_monitor.h"

#include <ns3/callback.h>
#include <ns3/simulator.h>

namespace rlpos {

TrafficMonitor::TrafficMonitor(const ns3::ApplicationContainer& senders,
                               const ns3::ApplicationContainer& sinks) {
  for (std::size_t i = 0; i < senders.GetN(); ++i) {
    senders.Get(i)->TraceConnectWithoutContext(
        "TxWithSeqTsSize", ns3::MakeCallback(&TrafficMonitor::OnSent, this).Bind(i));
    sinks.Get(i)->TraceConnectWithoutContext(
        "RxWithSeqTsSize", ns3::MakeCallback(&TrafficMonitor::OnReceived, this).Bind(i));
  }
  flows_.assign(senders.GetN(), FlowAccumulator({0.0, 0.0}));
}

void TrafficMonitor::Restart(MeasurementWindow window) {
  window_ = window;
  flows_.assign(flows_.size(), FlowAccumulator(window));
}

void TrafficMonitor::OnSent(std::size_t flow, ns3::Ptr<const ns3::Packet>, const ns3::Address&,
                            const ns3::Address&, const ns3::SeqTsSizeHeader&) {
  flows_[flow].OnSent(ns3::Simulator::Now().GetSeconds());
}

void TrafficMonitor::OnReceived(std::size_t flow, ns3::Ptr<const ns3::Packet> packet,
                                const ns3::Address&, const ns3::Address&,
                                const ns3::SeqTsSizeHeader& header) {
  // The sink hands over the payload without the header; the application sent both.
  flows_[flow].OnReceived(header.GetTs().GetSeconds(), ns3::Simulator::Now().GetSeconds(),
                          packet->GetSize() + header.GetSerializedSize());
}

}  // namespace rlpos
