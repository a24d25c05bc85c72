#pragma once
// The scenario built in ns-3: buildings, UEs sending to a sink on the UAV over Wi-Fi, the
// obstacle-aware channel, and the monitors. One instance owns the ns-3 simulation: it calls
// Simulator::Destroy when it goes away, so only one may exist at a time per process (a second
// construction throws std::runtime_error saying so). The analytic fidelity does not use it
// (worker/env/analytic).
#include <memory>
#include <vector>

#include "common/metrics/run_metrics.h"
#include "common/scenario/scenario.h"

namespace rlpos {

struct LinkState {
  bool los = false;
  double snr_db = 0.0;
};

// kOn gives every UE a radio per UAV, each in that UAV's BSS (a subnet per UAV), so that
// Reassociate can move its flow; kOff, one radio, in its serving UAV's BSS.
enum class Handover { kOff, kOn };

// kFixed holds each UAV where SetUavPositions puts it; kFlies moves it along the legs FlyUav
// gives it (ns-3's WaypointMobilityModel), so that the links change during the run.
enum class UavMotion { kFixed, kFlies };

class UavNetwork {
 public:
  // Validates the ns-3 side of the scenario (TypeIds, attributes, channels), then builds it with
  // UAV u at `placement[u]`. Each UE is served by the UAV the association rule gives at the
  // positions given here (environment/association.h), and changes UAV only through Reassociate.
  // Throws ConfigError on a bad scenario, std::invalid_argument on a placement of another size.
  UavNetwork(const Scenario& scenario, const Placement& placement,
             Handover handover = Handover::kOff, UavMotion motion = UavMotion::kFixed);
  ~UavNetwork();
  UavNetwork(const UavNetwork&) = delete;
  UavNetwork& operator=(const UavNetwork&) = delete;

  const Scenario& scenario() const;
  // Move the UAVs at once (UavMotion::kFixed; std::logic_error on a network whose UAVs fly).
  void SetUavPositions(const Placement& placement);
  void SetUavPosition(std::size_t uav, const Vec3& position);
  // UAV `uav` flies from where it is now to `to` in a straight line at constant velocity,
  // arriving at absolute time `arrive_at` (s, rounded to whole nanoseconds as the UEs' knots
  // are), and holds there. A leg to where it is already is a hold; a leg given before the last
  // one ends starts at its end. Throws std::logic_error on a network built with UavMotion::kFixed
  // or for an arrival before the last leg's, std::invalid_argument for one not after now.
  void FlyUav(std::size_t uav, const Vec3& to, double arrive_at);
  Placement UavPositions() const;
  // Each UE's position as ns-3's mobility model gives it now (scenario.ues' order): a moving
  // UE's trajectory (common/mobility) at the simulator's time.
  std::vector<Vec3> UePositions() const;
  // Applies the association rule to the links as they are now (after UAVs or UEs moved) and
  // hands over each UE whose serving UAV changes: its flow to the old UAV stops, and a new one
  // from its radio in the new UAV's BSS to a sink on that UAV (UDP: from the next packet; TCP: a
  // new connection, from slow start) starts at once if that radio is associated
  // (make-before-break), else once ns-3's STA has associated it. Returns the number of UEs
  // handed over; throws std::logic_error on a network built with Handover::kOff.
  int Reassociate();
  // UEs handed over since the network was built.
  std::size_t Handovers() const;
  // Per UE, its serving UAV if the UE's radio for it is associated with that UAV's AP now (as
  // its MAC has it), else -1: not associated (yet, or out of reach), and always in ad hoc mode.
  std::vector<int> AssociatedAps() const;
  // The serving UAV's index, per UE (a UE being handed over: the UAV it is joining).
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
