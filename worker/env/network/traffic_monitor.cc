#include "worker/env/network/traffic_monitor.h"

#include <ns3/callback.h>
#include <ns3/simulator.h>

namespace rlpos {

TrafficMonitor::TrafficMonitor(std::size_t flows) : flows_(flows, FlowAccumulator({0.0, 0.0})) {}

void TrafficMonitor::AttachSender(std::size_t flow, const ns3::Ptr<ns3::Application>& sender) {
  sender->TraceConnectWithoutContext("TxWithSeqTsSize",
                                     ns3::MakeCallback(&TrafficMonitor::OnSent, this).Bind(flow));
}

void TrafficMonitor::AttachSink(std::size_t flow, const ns3::Ptr<ns3::Application>& sink) {
  sink->TraceConnectWithoutContext("RxWithSeqTsSize",
                                   ns3::MakeCallback(&TrafficMonitor::OnReceived, this).Bind(flow));
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
