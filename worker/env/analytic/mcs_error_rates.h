#pragma once
// What the configured PHY's error rate model says of each MCS, computed once: the minimum SNR of
// each MCS (as ns-3's IdealWifiManager derives it, at the rate manager's BER threshold) and the
// success rate of one MPDU of the scenario's size at any SNR.
#include <memory>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

class McsErrorRates {
 public:
  // Uses ns-3 objects (the error rate model, the rate manager): the caller keeps other threads
  // out of ns-3's registries meanwhile. Throws ConfigError on a bad rate manager spec.
  explicit McsErrorRates(const Scenario& scenario);
  ~McsErrorRates();
  McsErrorRates(const McsErrorRates&) = delete;
  McsErrorRates& operator=(const McsErrorRates&) = delete;

  // Minimum SNR (dB) per MCS (index = MCS).
  const std::vector<double>& ThresholdsDb() const { return thresholds_db_; }
  // Probability that an MPDU of the scenario's size sent at `mcs` arrives at `snr_db`.
  double MpduSuccessRate(int mcs, double snr_db) const;

 private:
  // ns-3.37's TableBasedErrorRateModel rounds the SNR to 0.01 dB before it looks up its AWGN
  // tables, so where it has a table the rate is a function of that rounded SNR: a table of it,
  // over the range where it is neither 0 nor 1. The MCSs it has no table for (HE MCS 10-11 with
  // BCC) go to its continuous fallback, which is asked at each call.
  struct PerMcs {
    bool tabled = false;
    long first_step = 0;          // the 0.01 dB step of success[0]
    std::vector<double> success;  // per 0.01 dB step from first_step
    double below = 0.0;           // the rate under the table, and over it
    double above = 1.0;
  };
  std::vector<double> thresholds_db_;
  std::vector<PerMcs> per_mcs_;
  struct Fallback;  // the ns-3 model and transmissions the untabled MCSs need
  std::unique_ptr<Fallback> fallback_;
};

}  // namespace rlpos
