#pragma once
// The order in which the report shows track runs: scenarios in the order they first come (the
// campaign's), then held positioners before tracking ones (TrackPositionerNames()), named
// policies after the rest, by label. The summary, the curves and the time series share it.
#include <cstddef>
#include <string>
#include <tuple>
#include <vector>

namespace rlpos {

using TrackGroupKey = std::tuple<std::size_t, std::size_t, std::string>;

class TrackGroupOrder {
 public:
  // Scenarios are numbered as they are first seen.
  TrackGroupKey KeyOf(const std::string& scenario, const std::string& label);

 private:
  std::vector<std::string> scenarios_;
};

}  // namespace rlpos
