#include "coordinator/reporting/track_groups.h"

#include <algorithm>

#include "common/campaign/campaign_spec.h"

namespace rlpos {

TrackGroupKey TrackGroupOrder::KeyOf(const std::string& scenario, const std::string& label) {
  auto found = std::find(scenarios_.begin(), scenarios_.end(), scenario);
  if (found == scenarios_.end())
    found = scenarios_.insert(scenarios_.end(), scenario);
  const auto& names = TrackPositionerNames();
  const auto rank =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), label) - names.begin());
  return {static_cast<std::size_t>(found - scenarios_.begin()), rank, label};
}

std::map<TrackGroupKey, std::vector<const TrackRunRow*>> GroupTrackRuns(
    const std::vector<TrackRunRow>& rows) {
  TrackGroupOrder order;
  std::map<TrackGroupKey, std::vector<const TrackRunRow*>> groups;
  for (const TrackRunRow& r : rows)
    groups[order.KeyOf(r.scenario, r.label)].push_back(&r);
  return groups;
}

}  // namespace rlpos
