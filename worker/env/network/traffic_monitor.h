#pragma once
// Counts application packets per UE flow (sent by the UE's app, received by a UAV's sink)
// against the current measurement window, using SeqTsSizeHeader timestamps. A flow may gain
// senders and sinks while it runs: a UE handed over to another UAV sends to that UAV's sink.
#include <ns3/address.h>
#include <ns3/application.h>
#include <ns3/packet.h>
#include <ns3/seq-ts-size-header.h>

#include <vector>

#include "common/metrics/run_metrics.h"

namespace rlpos {

class TrafficMonitor {
 public:
  explicit TrafficMonitor(std::size_t flows);
  // Counts what `sender` sends (its "TxWithSeqTsSize") and `sink` receives ("RxWithSeqTsSize")
  // as UE `flow`'s traffic.
  void AttachSender(std::size_t flow, const ns3::Ptr<ns3::Application>& sender);
  void AttachSink(std::size_t flow, const ns3::Ptr<ns3::Application>& sink);
  void Restart(MeasurementWindow window);
  const std::vector<FlowAccumulator>& flows() const { return flows_; }
  MeasurementWindow window() const { return window_; }

 private:
  void OnSent(std::size_t flow, ns3::Ptr<const ns3::Packet> packet, const ns3::Address& from,
              const ns3::Address& to, const ns3::SeqTsSizeHeader& header);
  void OnReceived(std::size_t flow, ns3::Ptr<const ns3::Packet> packet, const ns3::Address& from,
                  const ns3::Address& to, const ns3::SeqTsSizeHeader& header);
  MeasurementWindow window_;
  std::vector<FlowAccumulator> flows_;
};

}  // namespace rlpos
