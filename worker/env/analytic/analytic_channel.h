#pragma once
// The analytic fidelity's link model as a value: built from a scenario once, it owns all it uses
// (the building geometry, its own loss model objects and two mobility models for the two ends,
// the MCS thresholds and MPDU success rates) and touches no process-wide ns-3 state once built.
// So any number may live in one process, and several threads may each use their own at once.
// One value is used by one thread at a time (ns-3's reference counts are not atomic).
//
// The numbers are those of the packet-level channel (UavNetwork::LinksTo, McsSnrThresholdsDb,
// MpduSuccessRate) for the same scenario and positions; a test holds them equal.
#include <cstddef>
#include <memory>
#include <vector>

#include "common/geometry/obstacles.h"
#include "common/scenario/scenario.h"
#include "worker/env/analytic/mcs_error_rates.h"

namespace rlpos {

// One UE's uplink to a UAV: LoS by the building geometry, SNR by the scenario's loss model.
struct UplinkState {
  bool los = false;
  double snr_db = 0.0;
};

class AnalyticChannel {
 public:
  // Builds the ns-3 objects it keeps under a process-wide lock, so that constructions on two
  // threads are safe. Throws ConfigError on a scenario the analytic model cannot follow: a bad
  // ns-3 spec, a loss model that draws random numbers or needs ns-3's building list.
  explicit AnalyticChannel(const Scenario& scenario);
  ~AnalyticChannel();
  AnalyticChannel(const AnalyticChannel&) = delete;
  AnalyticChannel& operator=(const AnalyticChannel&) = delete;

  // UE `ue`'s uplink to a UAV at `uav`. Not const: it moves the value's own mobility models.
  UplinkState Uplink(std::size_t ue, const Vec3& uav);
  // The UEs where they are now (one per UE, in the scenario's order; the scenario's positions
  // until this is called): moving UEs keep the same channel, only their ends move.
  // Throws std::invalid_argument for another count.
  void SetUePositions(const std::vector<Vec3>& positions);
  const std::vector<Vec3>& UePositions() const { return ues_; }
  // The Wi-Fi channel number of each UAV.
  const std::vector<int>& UavChannels() const { return channels_; }
  // Minimum SNR (dB) per MCS, as ns-3's IdealWifiManager derives it.
  const std::vector<double>& McsSnrThresholdsDb() const { return rates_->ThresholdsDb(); }
  // Probability that an MPDU of the scenario's size sent at `mcs` arrives at `snr_db`.
  double MpduSuccessRate(int mcs, double snr_db) const {
    return rates_->MpduSuccessRate(mcs, snr_db);
  }

 private:
  double SnrDb(const Vec3& ue, const Vec3& uav, bool los);
  struct LossModels;  // the ns-3 objects (pimpl: no ns-3 header here)
  Obstacles geometry_;
  std::vector<Vec3> ues_;
  double tx_dbm_ = 0.0;  // transmit power plus the sender's antenna gain
  double rx_gain_db_ = 0.0;
  double noise_floor_dbm_ = 0.0;
  std::vector<int> channels_;
  std::unique_ptr<LossModels> loss_;
  std::unique_ptr<McsErrorRates> rates_;
};

}  // namespace rlpos
