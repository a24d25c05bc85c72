#pragma once
// A guard against an ns-3.37 bug in the Block Ack recipient. ns-3.37 holds a recipient's Block
// Ack agreement "pending" until the originator acknowledges the recipient's ADDBA Response. When
// that Ack is lost, the originator (which did get the Response) already sends A-MPDUs under the
// agreement; the recipient then schedules a Normal Ack for every MPDU in the A-MPDU and, at the
// A-MPDU's end, a Block Ack from an agreement it looks up without checking
// (HtFrameExchangeManager::EndReceiveAmpdu dereferences m_agreements.end(); the NS_ASSERT is
// compiled out in release builds). The copy of that non-agreement then fails with
// std::bad_alloc or worse. ns-3.38 removed the pending state (the agreement is established as the
// Response is sent).
//
// The guard sits between each radio's PHY and its frame exchange manager and drops such an
// A-MPDU whole, as if it had not been decoded: the originator misses its Block Ack and recovers
// (BlockAckReq, retransmission) once the recipient's ADDBA Response is acknowledged. Every other
// frame passes through unchanged, so runs that never meet the bug are untouched.
#include <ns3/net-device-container.h>

#include <cstddef>

namespace rlpos {

// Installs the guard on every Wi-Fi device in `devices` with an HT or later frame exchange
// manager (the ones that aggregate). Call after the devices are installed.
void GuardBlockAckRecipients(const ns3::NetDeviceContainer& devices);

// How many A-MPDUs the guard has dropped in this process.
std::size_t AmpdusDroppedWithoutAgreement();

}  // namespace rlpos
