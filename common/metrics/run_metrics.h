#pragma once
// How the eval metrics are measured: per flow against the measurement window, then summed over
// the UEs of the run and of each UAV. What each metric means is its entry in EvalMetricTable()
// (metrics/eval_metrics.h). The demand check: the MCS a UE's demand needs -> that MCS's minimum
// SNR -> met if SNR >= it.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/metrics/eval_metrics.h"
#include "common/phy/mcs_table.h"
#include "common/scenario/scenario.h"

namespace rlpos {

struct MeasurementWindow {
  double start = 0.0;  // s
  double end = 0.0;    // s
  bool Holds(double t) const { return t >= start && t < end; }
  double Length() const { return end - start; }
};

// Counts one flow (one UE -> UAV) against a window. Fed by the simulator's traces.
class FlowAccumulator {
 public:
  explicit FlowAccumulator(MeasurementWindow window) : window_(window) {}
  void OnSent(double sent_at);
  void OnReceived(double sent_at, double received_at, std::uint64_t bytes);

  double ThroughputMbps() const;
  double MeanDelayMs() const;  // NaN when nothing was received
  double LossRatio() const;    // NaN when nothing was sent
  std::uint64_t SentInWindow() const { return sent_; }
  std::uint64_t ReceivedInWindow() const { return received_packets_; }
  double DelaySumS() const { return delay_sum_s_; }
  std::uint64_t BytesInWindow() const { return received_bytes_; }
  std::uint64_t DeliveredOfSentInWindow() const { return delivered_of_sent_; }

 private:
  MeasurementWindow window_;
  std::uint64_t sent_ = 0;
  std::uint64_t delivered_of_sent_ = 0;
  std::uint64_t received_packets_ = 0;
  std::uint64_t received_bytes_ = 0;
  double delay_sum_s_ = 0.0;
};

struct DemandCheck {
  int required_mcs = -1;  // -1: no MCS of this PHY carries the demand
  double min_snr_db = 0.0;
  bool met = false;
};
DemandCheck CheckDemand(const PhyProfile& phy, double demand_mbps, double snr_db);

struct UeMetrics {
  std::string name;
  int uav = 0;  // index of the serving UAV
  bool los = false;
  double snr_db = 0.0;
  double demand_mbps = 0.0;
  DemandCheck demand;
  double throughput_mbps = 0.0;
  double mean_delay_ms = 0.0;
  double loss_ratio = 0.0;
  std::uint64_t sent = 0;
  std::uint64_t received = 0;
};

// Who a UAV is in a run: its name, where it is, its Wi-Fi channel.
struct UavIdentity {
  std::string name;
  Vec3 position;
  int channel = 0;
};

// One UAV's share of a run: the same definitions over the UEs it serves (n_los: those with a
// clear line to it). worst UE and Jain's index are NaN when it serves nobody.
struct UavMetrics : UavMetricFields<double> {
  UavIdentity uav;
};

// The metrics (RunMetricFields, eval_metrics.h) and what they were measured on.
struct RunMetrics : RunMetricFields<double> {
  Vec3 position;  // of the first UAV (the only one in a single-UAV scenario)
  MeasurementWindow window;
  std::uint64_t run = 0;
  std::vector<UeMetrics> ues;
  std::vector<UavMetrics> uavs;  // one per UAV, the scenario's order
};

// Jain's fairness index of `values` (NaN when they sum to 0 or there are none).
double JainIndex(const std::vector<double>& values);

// Aggregates per-flow accumulators (one per UE, same order as `ues`) into the run's metrics,
// overall and per UAV (a UE counts for the UAV of its `uav` index).
RunMetrics Summarize(const std::vector<UavIdentity>& uavs, MeasurementWindow window,
                     std::uint64_t run, const std::vector<FlowAccumulator>& flows,
                     std::vector<UeMetrics> ues);
// One UAV named "uav" at `position`.
RunMetrics Summarize(const Vec3& position, MeasurementWindow window, std::uint64_t run,
                     const std::vector<FlowAccumulator>& flows, std::vector<UeMetrics> ues);

// "uavs" (per-UAV metrics) is written only for more than one UAV: with one it repeats the run's.

nlohmann::json ToJson(const RunMetrics& metrics);

// A metric's value in JSON, which has no NaN: an undefined one (no packet) is null.
nlohmann::json MetricJson(double x);

}  // namespace rlpos
