#include "coordinator/web/track_frames.h"

#include <algorithm>
#include <cmath>

#include "common/mobility/ue_trajectories.h"
#include "common/scenario/scenario_parser.h"
#include "coordinator/reporting/run_groups.h"

namespace rlpos::web {
namespace {

using nlohmann::json;

// 0.1 m is finer than a marker on the map and keeps 600 frames of many UEs small.
double Tenth(double v) {
  return std::round(v * 10.0) / 10.0;
}

// The UEs' walks in a track job: the scenario at its RngRun (simulation.run, as `rlpos-sim track
// --RngRun` overrides it), drawn up to the run's duration (RunTrack sets simulation.duration, the
// trajectories' horizon, to it).
std::vector<UeTrajectory> TrackJobTrajectories(json document, std::int64_t rng_run,
                                               double duration) {
  ApplyOverrides(document, {"simulation.run=" + std::to_string(rng_run)});
  Scenario scenario = ParseScenario(document);
  scenario.simulation.duration = duration;
  return UeTrajectories(scenario);
}

json UeFrames(const std::vector<UeTrajectory>& trajectories, const std::vector<double>& times) {
  json frames = json::array();
  for (double t : times) {
    json frame = json::array();
    for (const UeTrajectory& trajectory : trajectories) {
      const Vec3 p = trajectory.PositionAt(t);
      frame.push_back({Tenth(p.x), Tenth(p.y)});
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

// One positioner's first run, interval by interval.
struct PositionerRun {
  std::int64_t rng_run = 0;
  std::vector<double> times;
  json uavs = json::array();  // per time, [x, y, z] per UAV
};

}  // namespace

std::map<std::string, ScenarioTracks> TracksByScenario(
    const std::vector<TrackIntervalRecord>& intervals, const std::vector<TrackRunRow>& runs) {
  std::map<std::string, ScenarioTracks> out;
  for (const TrackIntervalRecord& record : intervals)
    out[record.scenario].intervals.push_back(&record);
  for (const TrackRunRow& run : runs) {
    const auto it = out.find(run.scenario);
    if (it != out.end())
      it->second.durations[{run.label, run.rng_run}] = run.duration_s;
  }
  return out;
}

json TrackFramesJson(const json& document, const ScenarioTracks& tracks) {
  std::map<std::string, PositionerRun> by_label;
  for (const TrackIntervalRecord* record : tracks.intervals) {
    PositionerRun& run = by_label[record->label];
    if (run.times.empty())
      run.rng_run = record->rng_run;
    if (record->rng_run != run.rng_run)
      continue;  // only the first run is read; another would be out of step
    run.times.push_back(record->row.time_s);
    json frame = json::array();
    for (const Vec3& uav : record->row.positions)
      frame.push_back({Tenth(uav.x), Tenth(uav.y), Tenth(uav.z)});
    run.uavs.push_back(std::move(frame));
  }
  std::vector<std::string> order;
  for (const auto& entry : by_label)
    order.push_back(entry.first);
  std::sort(order.begin(), order.end(), ReportLabelLess);

  std::map<std::int64_t, std::vector<double>> times_of_run;
  std::map<std::int64_t, json> runs;  // by RngRun
  json positioners = json::array();
  for (const std::string& label : order) {
    PositionerRun& run = by_label[label];
    const auto duration = tracks.durations.find({label, run.rng_run});
    if (duration == tracks.durations.end())
      continue;  // its run row and its intervals are written together: not seen
    const auto [known, added] = times_of_run.emplace(run.rng_run, run.times);
    // The track jobs of a scenario share the campaign's duration and the scenario's decision
    // interval, hence their interval ends; one that did not would play out of step with its UEs.
    if (!added && known->second != run.times)
      continue;
    if (added) {
      runs[run.rng_run] = {
          {"rng_run", run.rng_run},
          {"duration", duration->second},
          {"times", run.times},
          {"ues",
           UeFrames(TrackJobTrajectories(document, run.rng_run, duration->second), run.times)}};
    }
    positioners.push_back(
        {{"positioner", label}, {"rng_run", run.rng_run}, {"uavs", std::move(run.uavs)}});
  }
  json run_list = json::array();
  for (auto& entry : runs)
    run_list.push_back(std::move(entry.second));
  return {{"runs", std::move(run_list)}, {"positioners", std::move(positioners)}};
}

}  // namespace rlpos::web
