#include "worker/programs/rlpos_sim/track_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "common/config/config_error.h"
#include "common/metrics/run_metrics.h"
#include "common/scenario/names.h"
#include "common/scenario/number_text.h"
#include "common/scenario/placement_json.h"
#include "worker/positioning/track/track_positioner.h"
#include "worker/positioning/track/track_run.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {
namespace {

// A positioner whose every decision another part makes (the RL module's policy).
class DecidingTrackPositioner : public TrackPositioner {
 public:
  explicit DecidingTrackPositioner(TrackDecision decide) : decide_(std::move(decide)) {}
  Placement Decide(const std::vector<Vec3>& ue_positions, const Placement& uavs_now) override {
    return decide_(ue_positions, uavs_now);
  }

 private:
  TrackDecision decide_;
};

std::size_t ScoredIntervals(const TrackResult& r) {
  std::size_t n = 0;
  for (const TrackInterval& i : r.intervals)
    n += i.scored ? 1 : 0;
  return n;
}

nlohmann::json ResultJson(const Scenario& s, const TrackCommand& t, const TrackResult& r) {
  nlohmann::json uavs = nlohmann::json::array();
  for (std::size_t u = 0; u < r.uavs.size(); ++u) {
    const TrackUavSummary& summary = r.uavs[u];
    uavs.push_back({{"name", s.uavs[u].name},
                    {"distance_flown_m", summary.distance_flown_m},
                    {"mean_ues_served", summary.mean_ues_served},
                    {"los_share", summary.los_share},
                    {"outage_share", summary.outage_share}});
  }
  nlohmann::json series = nlohmann::json::array();
  const double n_ues = static_cast<double>(s.ues.size());
  for (const TrackInterval& i : r.intervals) {
    nlohmann::json interval = {{"time", i.time},
                               {"scored", i.scored},
                               {"reward", i.reward},
                               {"throughput_mbps", i.throughput_mbps},
                               {"los_share", i.n_los / n_ues},
                               {"n_los", i.n_los},
                               {"demands_met", i.demands_met},
                               {"positions", PlacementJson(i.positions)}};
    if (t.fidelity == "packet")
      interval["mean_delay_ms"] = MetricJson(i.mean_delay_ms);
    if (s.uavs.size() > 1)
      interval["serving_uav"] = i.serving;
    series.push_back(interval);
  }
  nlohmann::json out = {{"scenario", s.name},
                        {"positioner", t.positioner},
                        {"fidelity", t.fidelity},
                        {"duration", t.duration},
                        {"decision_interval", s.env.decision_interval},
                        {"run", s.simulation.run},
                        {"intervals", r.intervals.size()},
                        {"n_ues", s.ues.size()},
                        {"scored_intervals", ScoredIntervals(r)},
                        {"uavs", uavs},
                        {"series", series}};
  for (const TrackMetricDef& m : kTrackMetrics)
    out[m.key] = MetricJson(r.metrics.*(m.field));
  if (t.fidelity == "packet")
    out["warmup"] = s.simulation.warmup;
  if (!t.policy.empty())
    out["policy"] = t.policy;
  return out;
}

void PrintResult(const Scenario& s, const TrackCommand& t, const TrackResult& r) {
  std::printf("%s in %s, %s s in %zu intervals of %s s, RngRun %llu, %s\n", t.positioner.c_str(),
              s.name.c_str(), FormatNumber(t.duration).c_str(), r.intervals.size(),
              FormatNumber(s.env.decision_interval).c_str(),
              static_cast<unsigned long long>(s.simulation.run), t.fidelity.c_str());
  if (ScoredIntervals(r) < r.intervals.size()) {
    std::printf("  (the %zu intervals that start within the %s s warm-up are not scored)\n",
                r.intervals.size() - ScoredIntervals(r), FormatNumber(s.simulation.warmup).c_str());
  }
  for (const TrackMetricDef& m : kTrackMetrics) {
    const double v = r.metrics.*(m.field);
    if (std::isfinite(v))
      std::printf("  %-22s %.4f\n", m.key, v);
  }
  if (s.uavs.size() < 2)
    return;
  std::printf("per UAV:  distance_flown_m  mean_ues_served  los_share  outage_share\n");
  for (std::size_t u = 0; u < r.uavs.size(); ++u) {
    const TrackUavSummary& summary = r.uavs[u];
    std::printf("  %-6s  %16.1f  %15.2f  %9.4f  %12.4f\n", s.uavs[u].name.c_str(),
                summary.distance_flown_m, summary.mean_ues_served, summary.los_share,
                summary.outage_share);
  }
}

}  // namespace

void AddTrack(CLI::App& app, TrackCommand& t, CommonOptions& options) {
  t.command = app.add_subcommand(
      "track",
      "Fly a run in which the UEs move: the UAVs follow a positioner at their speed limits");
  t.command->add_option("--scenario", options.scenario_file, kScenarioHelp)->required();
  t.command
      ->add_option("--positioner", t.positioner,
                   Choices(kTrackPositioners) +
                       "; the *-track ones and rl decide again every env.decision_interval, the "
                       "others once for t = 0 (offsets: not in track)")
      ->required()
      ->check(CLI::IsMember(NameList(kTrackPositioners)));
  t.command->add_option("--policy", t.policy,
                        "rl: a policy for any scenario (rlpos-sim train --generated, or a shipped "
                        "one's name: generalist-1uav), flown greedy from where the UAVs are at "
                        "every decision");
  t.command->add_option("--duration", t.duration, "Seconds of the run")->required();
  t.command->add_option("--RngRun,--run", t.run, "RngRun: the UEs' trajectories (simulation.run)")
      ->required()
      ->check(CLI::NonNegativeNumber);
  t.command
      ->add_option("--fidelity", t.fidelity,
                   Choices(kFidelities) +
                       " (default analytic; packet: one ns-3 run in which the UAVs fly, "
                       "intervals in simulation.warmup not scored)")
      ->check(CLI::IsMember(NameList(kFidelities)));
  t.command->add_flag("--json", t.json, "Print the result and the per-interval series as JSON");
}

int RunTrackCommand(const CommonOptions& options, const TrackCommand& t) {
  if (!t.policy.empty() && t.positioner != "rl")
    throw ConfigError("--policy", "only the rl positioner flies a policy, not " + t.positioner);
  const Scenario s = LoadScenarioFor(options, {"simulation.run=" + std::to_string(t.run)});
  std::unique_ptr<TrackPositioner> positioner;
  if (t.positioner == "rl") {
    if (t.policy.empty())
      throw ConfigError("--policy", "is required for the rl positioner in track");
    positioner = std::make_unique<DecidingTrackPositioner>(RlTrackDecision(options, t.policy));
  } else {
    positioner = MakeTrackPositioner(t.positioner, s);
  }
  const TrackResult result =
      RunTrack(s, *positioner, t.duration,
               t.fidelity == "packet" ? TrackFidelity::kPacket : TrackFidelity::kAnalytic);
  if (t.json)
    std::cout << ResultJson(s, t, result).dump(2) << std::endl;
  else
    PrintResult(s, t, result);
  return kExitOk;
}

}  // namespace rlpos::sim
