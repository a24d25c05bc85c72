#include "worker/track/track_run.h"

#include <cmath>

#include "common/config/config_error.h"
#include "common/metrics/run_metrics.h"
#include "common/mobility/ue_trajectories.h"
#include "common/scenario/number_text.h"
#include "worker/gym/reward.h"
#include "worker/track/uav_flight.h"
#include "worker/uav_env/analytic_evaluator.h"

namespace rlpos {
namespace {

double Distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

std::vector<Vec3> PositionsAt(const std::vector<UeTrajectory>& trajectories, double t) {
  std::vector<Vec3> positions;
  positions.reserve(trajectories.size());
  for (const UeTrajectory& trajectory : trajectories)
    positions.push_back(trajectory.PositionAt(t));
  return positions;
}

}  // namespace

TrackResult RunTrack(const Scenario& scenario, TrackPositioner& positioner, double duration) {
  const double interval = scenario.env.decision_interval;
  // A hair of tolerance: 60 / 0.1 is 599.999... in binary.
  const auto n = static_cast<std::size_t>(std::floor(duration / interval + 1e-9));
  if (!(duration > 0) || n == 0) {
    throw ConfigError("--duration", "must be at least env.decision_interval (" +
                                        FormatNumber(interval) + " s), got " +
                                        FormatNumber(duration));
  }
  Scenario s = scenario;
  s.simulation.duration = duration;  // the trajectories' horizon, as eval --duration has it
  const std::vector<UeTrajectory> trajectories = UeTrajectories(s);
  const std::size_t k = s.uavs.size();
  const std::size_t n_ues = s.ues.size();
  const WifiSpec& w = s.wifi;
  const PhyProfile phy{w.standard, w.width_mhz, w.guard_interval_ns, w.spatial_streams};
  const auto reward = MakeReward(s.env.reward);
  AnalyticEvaluator analytic(s);

  TrackResult result;
  result.uavs.resize(k);
  std::vector<double> served(k), los(k), outage(k);
  Placement now = positioner.Decide(PositionsAt(trajectories, 0.0), s.InitialPlacement());
  for (std::size_t i = 0; i < n; ++i) {
    const double start = static_cast<double>(i) * interval;
    const double end = static_cast<double>(i + 1) * interval;
    TrackInterval record;
    record.time = end;
    record.targets = i == 0 ? now : positioner.Decide(PositionsAt(trajectories, start), now);
    // One after the other, each clear of where the others are (moved or not yet).
    for (std::size_t u = 0; u < k; ++u) {
      const Vec3 next = FlyToward(s, u, now, record.targets[u], interval);
      result.uavs[u].distance_flown_m += Distance(now[u], next);
      now[u] = next;
    }
    analytic.SetUePositions(PositionsAt(trajectories, end));
    const StepInfo info = analytic.Evaluate(now);
    record.reward = (*reward)(RewardInputOf(s, info.n_los, info.throughput_mbps, info.demands_met));
    record.throughput_mbps = info.throughput_mbps;
    record.n_los = info.n_los;
    record.demands_met = info.demands_met;
    record.positions = now;
    record.serving = info.serving;
    for (std::size_t ue = 0; ue < n_ues; ++ue) {
      const auto u = static_cast<std::size_t>(info.serving[ue]);
      served[u] += 1;
      los[u] += info.los[ue];
      // The same check as the evaluator's count of demands met, per UE.
      outage[u] += CheckDemand(phy, s.ues[ue].demand_mbps, info.snr_db[ue]).met ? 0 : 1;
    }
    result.mean_reward += record.reward;
    result.mean_throughput_mbps += record.throughput_mbps;
    result.los_share += info.n_los;
    result.outage_share += static_cast<double>(n_ues) - info.demands_met;
    result.intervals.push_back(std::move(record));
  }
  const double intervals = static_cast<double>(n);
  const double ue_intervals = intervals * static_cast<double>(n_ues);
  result.mean_reward /= intervals;
  result.mean_throughput_mbps /= intervals;
  result.los_share /= ue_intervals;
  result.outage_share /= ue_intervals;
  for (std::size_t u = 0; u < k; ++u) {
    TrackUavSummary& summary = result.uavs[u];
    result.distance_flown_m += summary.distance_flown_m;
    summary.mean_ues_served = served[u] / intervals;
    summary.los_share = served[u] > 0 ? los[u] / served[u] : 0.0;
    summary.outage_share = served[u] > 0 ? outage[u] / served[u] : 0.0;
  }
  return result;
}

}  // namespace rlpos
