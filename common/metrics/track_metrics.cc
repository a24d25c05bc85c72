#include "common/metrics/track_metrics.h"

namespace rlpos {

std::string TrackMetricsMarkdown() {
  std::string out =
      "| JSON key and `track_runs` column | Unit | Definition |\n"
      "|---|---|---|\n";
  for (const TrackMetricDef& m : kTrackMetrics) {
    out += std::string("| `") + m.key + "`" + (m.nullable ? " (nullable)" : "") + " | " + m.unit +
           " | " + m.doc + " |\n";
  }
  return out;
}

}  // namespace rlpos
