#pragma once
// The order in which the report shows track runs: scenarios in the order they first come (the
// campaign's), then held positioners before tracking ones (TrackPositionerNames()), named
// policies after the rest, by label. The summary, the curves and the time series share it.
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "common/store/track_rows.h"

namespace rlpos {

using TrackGroupKey = std::tuple<std::size_t, std::size_t, std::string>;

class TrackGroupOrder {
 public:
  // Scenarios are numbered as they are first seen.
  TrackGroupKey KeyOf(const std::string& scenario, const std::string& label);

 private:
  std::vector<std::string> scenarios_;
};

// The runs of each scenario and positioner, in that order.
std::map<TrackGroupKey, std::vector<const TrackRunRow*>> GroupTrackRuns(
    const std::vector<TrackRunRow>& rows);

}  // namespace rlpos
