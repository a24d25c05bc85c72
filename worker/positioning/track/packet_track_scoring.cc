// A track run at packet level: one ns-3 run in which the UEs walk (their waypoint mobility) and
// the UAVs fly each interval's legs (UavMotion::kFlies), measured interval by interval.
#include <algorithm>

#include "common/metrics/run_metrics.h"
#include "worker/env/network/uav_network.h"
#include "worker/positioning/track/track_scoring.h"
#include "worker/positioning/track/uav_flight.h"

namespace rlpos {
namespace {

class PacketScoring : public TrackScoring {
 public:
  PacketScoring(const Scenario& s, const Placement& start)
      : scenario_(s),
        network_(s, start, s.uavs.size() > 1 ? Handover::kOn : Handover::kOff, UavMotion::kFlies) {}

  std::vector<Vec3> UePositionsAt(double t) override {
    network_.RunUntil(t);
    return network_.UePositions();
  }

  IntervalScore FlyInterval(const Placement& from, const Placement& to, double start,
                            double end) override {
    network_.RunUntil(start);
    if (scenario_.uavs.size() > 1)
      network_.Reassociate();  // the rule on the links at the decision, as the env steps do
    for (std::size_t u = 0; u < to.size(); ++u) {
      const double seconds = FlightSeconds(scenario_.uavs[u], from[u], to[u]);
      // A leg of under a microsecond still arrives after now on ns-3's nanosecond clock.
      if (seconds > 0.0)
        network_.FlyUav(u, to[u], start + std::clamp(seconds, 1e-6, end - start));
    }
    network_.BeginMeasurement({start, end});
    network_.RunUntil(end);
    const RunMetrics m = network_.Measure();
    IntervalScore score;
    score.scored = start >= scenario_.simulation.warmup;
    score.throughput_mbps = m.aggregate_throughput_mbps;
    score.mean_delay_ms = m.mean_delay_ms;
    score.n_los = m.n_los;
    score.demands_met = m.demands_met;
    score.uavs = network_.UavPositions();  // ns-3's: where the flight took them
    for (const UeMetrics& ue : m.ues) {
      score.serving.push_back(ue.uav);
      score.los.push_back(ue.los ? 1 : 0);
      score.demand_met.push_back(ue.demand.met ? 1 : 0);
    }
    return score;
  }

 private:
  Scenario scenario_;
  UavNetwork network_;
};

}  // namespace

std::unique_ptr<TrackScoring> MakePacketScoring(const Scenario& scenario, const Placement& start) {
  return std::make_unique<PacketScoring>(scenario, start);
}

}  // namespace rlpos
