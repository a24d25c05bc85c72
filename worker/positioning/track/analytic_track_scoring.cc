// A track run scored by the analytic model: the UEs on their trajectories and the UAVs at the
// end of each interval, as `position` scores a placement.
#include <cmath>
#include <limits>

#include "common/metrics/run_metrics.h"
#include "common/mobility/ue_trajectories.h"
#include "worker/env/uav_env/analytic_evaluator.h"
#include "worker/positioning/track/track_scoring.h"

namespace rlpos {
namespace {

class AnalyticScoring : public TrackScoring {
 public:
  explicit AnalyticScoring(const Scenario& s)
      : scenario_(s),
        trajectories_(UeTrajectories(s)),
        phy_{s.wifi.standard, s.wifi.width_mhz, s.wifi.guard_interval_ns, s.wifi.spatial_streams},
        analytic_(s) {}

  std::vector<Vec3> UePositionsAt(double t) override {
    std::vector<Vec3> positions;
    positions.reserve(trajectories_.size());
    for (const UeTrajectory& trajectory : trajectories_)
      positions.push_back(trajectory.PositionAt(t));
    return positions;
  }

  IntervalScore FlyInterval(const Placement&, const Placement& to, double, double end) override {
    analytic_.SetUePositions(UePositionsAt(end));
    const StepInfo info = analytic_.Evaluate(to);
    IntervalScore score;
    score.throughput_mbps = info.throughput_mbps;
    score.mean_delay_ms = std::numeric_limits<double>::quiet_NaN();
    score.n_los = info.n_los;
    score.demands_met = info.demands_met;
    score.serving = info.serving;
    score.uavs = to;
    score.los.assign(info.los.begin(), info.los.end());
    for (std::size_t ue = 0; ue < scenario_.ues.size(); ++ue) {
      // The same check as the evaluator's count of demands met, per UE.
      score.demand_met.push_back(
          CheckDemand(phy_, scenario_.ues[ue].demand_mbps, info.snr_db[ue]).met ? 1 : 0);
    }
    return score;
  }

 private:
  Scenario scenario_;
  std::vector<UeTrajectory> trajectories_;
  PhyProfile phy_;
  AnalyticEvaluator analytic_;
};

}  // namespace

std::unique_ptr<TrackScoring> MakeAnalyticScoring(const Scenario& scenario) {
  return std::make_unique<AnalyticScoring>(scenario);
}

}  // namespace rlpos
