#pragma once
// Counts application packets per UE flow (sent by the UE's app, received by the UAV's sink)
// against the current measurement window, using SeqTsSizeHeader timestamps.
#include <ns3/application-container.h>
#include <ns3/address.h>
#include <ns3/packet.h>
#include <ns3/seq-ts-size-header.h>
#include <vector>

#include "metrics/run_metrics.h"

namespace rlpos {

class TrafficMonitor {
 public:
  // senders[i] and sinks[i] are UE i's application and its sink on the UAV.
  TrafficMonitor(const ns3::ApplicationContainer& senders, const ns3::ApplicationContainer& sinks);
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
