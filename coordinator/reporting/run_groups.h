#pragma once
// Groups the eval runs of a campaign per (scenario, positioner label) in report order, so that
// the summary table, the curves and the plots all list positioners the same way: the paper's
// order (baseline, positions 1-5, centroid, oracle, RL) rather than the store's alphabetical one.
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

// Report order of eval labels: AllPositioners() with "offsets" expanded, i.e. baseline,
// offset1..offset5, centroid, oracle, rl; "<label>@<algorithm>" after its plain label (in
// AllAlgorithms() order), each followed by its "@seed<N>" labels (by N);
// labels outside that list last, by name.
bool ReportLabelLess(const std::string& a, const std::string& b);

struct RunGroup {
  std::string scenario;
  std::string label;
  std::vector<const MetricRow*> runs;  // point into the rows given to GroupRuns, in their order
};

// Scenarios in the order they first appear in `rows`, labels in report order within each.
std::vector<RunGroup> GroupRuns(const std::vector<MetricRow>& rows);

}  // namespace rlpos
