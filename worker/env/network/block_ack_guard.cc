#include "worker/env/network/block_ack_guard.h"

#include <ns3/callback.h>
#include <ns3/ht-frame-exchange-manager.h>
#include <ns3/simulator.h>
#include <ns3/wifi-mac.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-phy.h>
#include <ns3/wifi-psdu.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "common/logging/log.h"

namespace rlpos {
namespace {

std::atomic<std::size_t>& Dropped() {
  static std::atomic<std::size_t> dropped{0};
  return dropped;
}

// True when `psdu` is (an MPDU of) an A-MPDU addressed to `fem` whose QoS data asks for an
// implicit Block Ack under an agreement `fem` has not established: exactly the A-MPDUs whose
// end ns-3.37's HtFrameExchangeManager::EndReceiveAmpdu mishandles. The PHY hands over each
// correct MPDU of an A-MPDU alone with no per-MPDU status, then the whole A-MPDU with it.
bool WithoutAgreement(const ns3::HtFrameExchangeManager& fem, const ns3::WifiPsdu& psdu,
                      const ns3::WifiTxVector& tx, const std::vector<bool>& per_mpdu_status) {
  const bool in_ampdu = per_mpdu_status.empty() || psdu.GetNMpdus() > 1;
  if (!in_ampdu || psdu.GetAddr1() != fem.GetAddress())
    return false;
  // HE trigger-based PPDUs and A-MPDUs carrying a Trigger frame are handled before that code.
  if (tx.IsUlMu() || std::any_of(psdu.begin(), psdu.end(),
                                 [](const auto& mpdu) { return mpdu->GetHeader().IsTrigger(); })) {
    return false;
  }
  const std::set<uint8_t> tids = psdu.GetTids();
  if (tids.size() != 1)
    return false;
  const uint8_t tid = *tids.begin();
  return psdu.GetAckPolicyForTid(tid) == ns3::WifiMacHeader::NORMAL_ACK &&
         !fem.GetBaAgreementEstablished(psdu.GetAddr2(), tid);
}

// The PHY's receive callback with the guard in front of the frame exchange manager's own.
// A raw pointer, as ns-3 binds it: the manager resets the callback when it is disposed.
void GuardedReceive(ns3::HtFrameExchangeManager* fem, ns3::Ptr<const ns3::WifiPsdu> psdu,
                    ns3::RxSignalInfo signal, ns3::WifiTxVector tx,
                    std::vector<bool> per_mpdu_status) {
  if (WithoutAgreement(*fem, *psdu, tx, per_mpdu_status)) {
    // Counted (and logged) once per A-MPDU: at its end, when the status of each MPDU is known.
    if (!per_mpdu_status.empty()) {
      ++Dropped();
      if (CurrentLogLevel() >= LogLevel::kDebug) {
        std::ostringstream message;
        message << "t=" << ns3::Simulator::Now().GetSeconds() << " s: dropped an A-MPDU from "
                << psdu->GetAddr2() << " to " << psdu->GetAddr1()
                << " sent under a Block Ack agreement the recipient has not established (its "
                   "ADDBA Response unacknowledged; an ns-3.37 bug)";
        Log(LogLevel::kDebug, message.str());
      }
    }
    return;
  }
  fem->Receive(psdu, signal, tx, std::move(per_mpdu_status));
}

}  // namespace

void GuardBlockAckRecipients(const ns3::NetDeviceContainer& devices) {
  for (uint32_t i = 0; i < devices.GetN(); ++i) {
    auto device = ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i));
    if (!device)
      continue;
    for (uint8_t link = 0; link < device->GetNPhys(); ++link) {
      auto fem = ns3::DynamicCast<ns3::HtFrameExchangeManager>(
          device->GetMac()->GetFrameExchangeManager(link));
      if (!fem)
        continue;  // before 802.11n: no A-MPDUs
      device->GetPhy(link)->SetReceiveOkCallback(
          ns3::MakeBoundCallback(&GuardedReceive, ns3::PeekPointer(fem)));
    }
  }
}

std::size_t AmpdusDroppedWithoutAgreement() {
  return Dropped();
}

}  // namespace rlpos
