#include "worker/positioning/track/track_run.h"

#include <cmath>
#include <limits>
#include <memory>

#include "common/config/config_error.h"
#include "common/scenario/number_text.h"
#include "common/stats/descriptive.h"
#include "worker/env/gym/reward.h"
#include "worker/positioning/track/track_scoring.h"
#include "worker/positioning/track/uav_flight.h"

namespace rlpos {
namespace {

double Distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

std::size_t IntervalsIn(double duration, double interval) {
  // A hair of tolerance: 60 / 0.1 is 599.999... in binary.
  const auto n = static_cast<std::size_t>(std::floor(duration / interval + 1e-9));
  if (!(duration > 0) || n == 0) {
    throw ConfigError("--duration", "must be at least env.decision_interval (" +
                                        FormatNumber(interval) + " s), got " +
                                        FormatNumber(duration));
  }
  return n;
}

double P5(const std::vector<double>& over_time) {
  return Quantile(over_time, 0.05);
}

// The metrics and the per-UAV shares over the scored intervals.
void Summarize(const Scenario& s, TrackResult& result) {
  const std::size_t k = s.uavs.size();
  const double n_ues = static_cast<double>(s.ues.size());
  std::vector<double> served(k), los(k), outage(k);
  std::vector<double> rewards, throughputs, los_shares, met_shares;
  double delays = 0.0, delay_sum = 0.0;
  for (const TrackInterval& i : result.intervals) {
    if (!i.scored)
      continue;
    rewards.push_back(i.reward);
    throughputs.push_back(i.throughput_mbps);
    los_shares.push_back(i.n_los / n_ues);
    met_shares.push_back(i.demands_met / n_ues);
    if (std::isfinite(i.mean_delay_ms)) {
      delay_sum += i.mean_delay_ms;
      delays += 1;
    }
    for (std::size_t ue = 0; ue < i.serving.size(); ++ue) {
      const auto u = static_cast<std::size_t>(i.serving[ue]);
      served[u] += 1;
      los[u] += i.los[ue];
      outage[u] += i.demand_met[ue] ? 0 : 1;
    }
  }
  const double intervals = static_cast<double>(rewards.size());
  TrackMetrics& m = result.metrics;
  m.mean_reward = Mean(rewards);
  m.reward_p5 = P5(rewards);
  m.mean_throughput_mbps = Mean(throughputs);
  m.throughput_p5_mbps = P5(throughputs);
  m.mean_delay_ms = delays > 0 ? delay_sum / delays : std::numeric_limits<double>::quiet_NaN();
  m.los_share = Mean(los_shares);
  m.los_share_p5 = P5(los_shares);
  m.outage_share = 1.0 - Mean(met_shares);
  m.demands_met_share_p5 = P5(met_shares);
  for (std::size_t i = 1; i < result.intervals.size(); ++i) {
    const std::vector<int>& before = result.intervals[i - 1].serving;
    const std::vector<int>& now = result.intervals[i].serving;
    for (std::size_t ue = 0; ue < now.size(); ++ue)
      m.handovers += now[ue] != before[ue] ? 1 : 0;
  }
  for (std::size_t u = 0; u < k; ++u) {
    TrackUavSummary& summary = result.uavs[u];
    m.distance_flown_m += summary.distance_flown_m;
    summary.mean_ues_served = served[u] / intervals;
    summary.los_share = served[u] > 0 ? los[u] / served[u] : 0.0;
    summary.outage_share = served[u] > 0 ? outage[u] / served[u] : 0.0;
  }
}

}  // namespace

TrackResult RunTrack(const Scenario& scenario, TrackPositioner& positioner, double duration,
                     TrackFidelity fidelity) {
  const double interval = scenario.env.decision_interval;
  const std::size_t n = IntervalsIn(duration, interval);
  Scenario s = scenario;
  s.simulation.duration = duration;  // the trajectories' horizon, as eval --duration has it
  const bool packet = fidelity == TrackFidelity::kPacket;
  if (packet && static_cast<double>(n - 1) * interval < s.simulation.warmup) {
    throw ConfigError("--duration", "leaves no interval after simulation.warmup (" +
                                        FormatNumber(s.simulation.warmup) +
                                        " s) at packet level, got " + FormatNumber(duration));
  }
  const auto reward = MakeReward(s.env.reward);
  const std::size_t k = s.uavs.size();

  // The t = 0 decision comes first: a packet-level network is built with the UAVs there. Every
  // trajectory starts at its UE's position.
  std::vector<Vec3> ues_at_start;
  for (const UeSpec& ue : s.ues)
    ues_at_start.push_back(ue.position);
  Placement now = positioner.Decide(ues_at_start, s.InitialPlacement());
  const std::unique_ptr<TrackScoring> scoring =
      packet ? MakePacketScoring(s, now) : MakeAnalyticScoring(s);

  TrackResult result;
  result.uavs.resize(k);
  for (std::size_t i = 0; i < n; ++i) {
    const double start = static_cast<double>(i) * interval;
    const double end = static_cast<double>(i + 1) * interval;
    TrackInterval record;
    record.time = end;
    record.targets = i == 0 ? now : positioner.Decide(scoring->UePositionsAt(start), now);
    // One after the other, each clear of where the others are (moved or not yet).
    const Placement from = now;
    for (std::size_t u = 0; u < k; ++u) {
      const Vec3 next = FlyToward(s, u, now, record.targets[u], interval);
      result.uavs[u].distance_flown_m += Distance(now[u], next);
      now[u] = next;
    }
    const IntervalScore score = scoring->FlyInterval(from, now, start, end);
    record.scored = score.scored;
    record.reward =
        (*reward)(RewardInputOf(s, score.n_los, score.throughput_mbps, score.demands_met));
    record.throughput_mbps = score.throughput_mbps;
    record.mean_delay_ms = score.mean_delay_ms;
    record.n_los = score.n_los;
    record.demands_met = score.demands_met;
    record.positions = score.uavs;
    record.serving = score.serving;
    record.los = score.los;
    record.demand_met = score.demand_met;
    result.intervals.push_back(std::move(record));
  }
  Summarize(s, result);
  return result;
}

}  // namespace rlpos
