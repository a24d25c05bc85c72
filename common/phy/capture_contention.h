#pragma once
// Contention among stations of unequal strength at one receiver. When preambles arrive together,
// ns-3's PHY locks onto the strongest and keeps it if its SINR clears the preamble detection
// threshold (ThresholdPreambleDetectionModel, 4 dB). A collision with a station that much weaker
// can then still end in a BlockAck for the stronger one ("capture"): it does not double its
// contention window, so strong stations win more transmit opportunities. The SNR the receiver
// reports for a captured PPDU is that of its overlapped part, a few dB, so IdealWifiManager sends
// the station's next A-MPDU at the lowest MCS, where it holds the channel up to the 5.484 ms PPDU
// limit. Packet-level runs in scenario A show both: per-UE throughput grows with the UE's SNR,
// and the aggregate falls as the SNRs at the UAV spread out (MCS 0 A-MPDUs appear only from
// stations 4 dB or more above others).
//
// The model extends Bianchi's fixed point (dcf_contention.h) to unequal stations: station i
// fails when another station transmits in the same slot, unless exactly one other does, it is at
// least `threshold_db` weaker, and the capture works out (probability `probability`; it depends
// on how the two PPDUs overlap, which the model does not follow).
#include <vector>

namespace rlpos {

struct CaptureParams {
  double threshold_db = 4.0;
  double probability = 0.0;  // 0: no capture, every collision fails for all
  int cw_min = 15;
  int cw_max = 1023;
};

struct CaptureShares {
  // Successful accesses of each station relative to the stations' mean (all 1 without capture).
  std::vector<double> access_weight;
  // Share of each station's successful accesses that come right after a capture.
  std::vector<double> capture_share;
};

// `snr_db`: each contending station's SNR at the receiver. `activity` in [0, 1]: how often the
// other stations are backlogged (1 when the channel is full); it scales their attempts.
CaptureShares ContendWithCapture(const std::vector<double>& snr_db, double activity,
                                 const CaptureParams& params);

}  // namespace rlpos
