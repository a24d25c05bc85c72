#pragma once
// What a scenario's map plays of its track runs (JSON): the interval ends of each positioner's
// first run, where its UAVs were at each (as stored) and where the UEs were (drawn again by the
// mobility code, as the track job drew them: UEs walk the same way for every positioner of one
// RngRun, so they are sent once per run).
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/store/track_rows.h"

namespace rlpos::web {

// One scenario's track runs: the intervals of each positioner's first run (TrackRunsRead::
// kFirstRunOnly, in interval order) and each such run's duration by (positioner, rng_run).
struct ScenarioTracks {
  std::vector<const TrackIntervalRecord*> intervals;
  std::map<std::pair<std::string, std::int64_t>, double> durations;
};

// Groups a campaign's track runs by scenario name.
std::map<std::string, ScenarioTracks> TracksByScenario(
    const std::vector<TrackIntervalRecord>& intervals, const std::vector<TrackRunRow>& runs);

// {"runs": [{"rng_run", "duration", "times": [s], "ues": [[[x, y] per UE] per time]}],
//  "positioners": [{"positioner", "rng_run", "uavs": [[[x, y, z] per UAV] per time]}]}, the
// positioners in report order, coordinates rounded to 0.1 m. `document`: the campaign's scenario
// document with its "set" applied. Throws ConfigError as ParseScenario and the mobility code do.
nlohmann::json TrackFramesJson(const nlohmann::json& document, const ScenarioTracks& tracks);

}  // namespace rlpos::web
