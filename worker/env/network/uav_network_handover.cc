// The handover: a UE whose serving UAV changes stops its flow to the old UAV and restarts it
// from its radio in the new UAV's BSS, once that radio is associated.
#include <ns3/bulk-send-application.h>
#include <ns3/onoff-application.h>
#include <ns3/simulator.h>
#include <ns3/socket.h>
#include <ns3/sta-wifi-mac.h>

#include <stdexcept>

#include "worker/env/network/association.h"
#include "worker/env/network/uav_network_impl.h"

namespace rlpos {
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

// With handover, every UE radio tells when it joins its UAV's BSS (OnRadioAssociated).
void UavNetwork::Impl::ConnectAssociationTraces() {
  for (std::size_t i = 0; handover && i < ue_devices.size(); ++i) {
    for (std::size_t u = 0; u < ue_devices[i].size(); ++u) {
      ue_devices[i][u]->GetMac()->TraceConnectWithoutContext(
          "Assoc", ns3::MakeCallback(&Impl::OnRadioAssociated, this).Bind(i, u));
    }
  }
}

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

}  // namespace rlpos
