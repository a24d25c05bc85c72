#pragma once
#include <ostream>

#include "metrics/run_metrics.h"
#include "scenario/scenario.h"

namespace rlpos {
// Human-readable table of one run's metrics.
void PrintMetricsTable(std::ostream& out, const Scenario& scenario, const RunMetrics& metrics);
}  // namespace rlpos
