#pragma once
#include <ostream>

#include "common/metrics/run_metrics.h"
#include "common/scenario/scenario.h"

namespace rlpos {
// Human-readable table of one run's metrics.
void PrintMetricsTable(std::ostream& out, const Scenario& scenario, const RunMetrics& metrics);
}  // namespace rlpos
