#pragma once
// The scenario built in ns-3: buildings, UEs sending to a sink on the UAV over Wi-Fi, the
// obstacle-aware channel, and the monitors. One instance owns the ns-3 simulation: it calls
// Simulator::Destroy when it goes away, so only one may exist at a time.
#include <memory>
#include <vector>

#include "metrics/run_metrics.h"
#include "scenario/scenario.h"

namespace rlpos {

struct LinkState {
  bool los = false;
  double snr_db = 0.0;
};

class UavNetwork {
 public:
  // Validates the ns-3 side of the scenario (TypeIds, attributes, channels), then builds it with
  // UAV u at `placement[u]`. Each UE associates with its serving UAV (environment/association.h)
  // at the positions given here and stays with it while the network lives. Throws ConfigError on
  // a bad scenario, std::invalid_argument on a placement of another size.
  UavNetwork(const Scenario& scenario, const Placement& placement);
  ~UavNetwork();
  UavNetwork(const UavNetwork&) = delete;
  UavNetwork& operator=(const UavNetwork&) = delete;

  const Scenario& scenario() const;
  void SetUavPositions(const Placement& placement);
  void SetUavPosition(std::size_t uav, const Vec3& position);
  Placement UavPositions() const;
  // The serving UAV's index, per UE.
  const std::vector<int>& Association() const;
  // The Wi-Fi channel number of each UAV.
  std::vector<int> UavChannels() const;

  // Geometric LoS (building geometry, whatever the loss model) and the SNR at UAV `uav` of each
  // UE's uplink as the channel's loss model gives it, now.
  std::vector<LinkState> LinksTo(std::size_t uav) const;
  // Each UE's link to its serving UAV, now.
  std::vector<LinkState> Links() const;

  // Minimum SNR (dB) of each MCS of the configured PHY (index = MCS), as ns-3's
  // IdealWifiManager derives it from the error rate model at its BER threshold.
  std::vector<double> McsSnrThresholdsDb() const;

  // Probability that an MPDU of `mpdu_bytes` sent at `mcs` arrives at `snr_db`, from the error
  // rate model the PHYs use (what a link loses to retransmissions at the rate it was given).
  double MpduSuccessRate(int mcs, double snr_db, int mpdu_bytes) const;

  // Starts a new measurement window for the traffic monitor (drops what was counted before).
  void BeginMeasurement(MeasurementWindow window);
  // Advances the simulation to absolute time `t` (s).
  void RunUntil(double t);
  double Now() const;
  // Metrics of the current window, with the link state taken now.
  RunMetrics Measure() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Builds the scenario with the UAVs fixed at `placement`, runs it for the scenario's duration
// (plus a short drain so that packets in flight at the end are not counted lost), and returns
// the metrics over [warmup, duration]. `on_progress(simulated_s)` is called every ~5 % if set.
RunMetrics EvaluatePosition(const Scenario& scenario, const Placement& placement,
                            void (*on_progress)(double now, double end) = nullptr);

}  // namespace rlpos
