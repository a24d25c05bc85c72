#pragma once
// Per scenario and track positioner: what the campaign's track runs say (ResultsReader::
// TrackRuns, view v_track_runs), for `rlpos-campaign results --track` and the results tables.
// Each metric of kTrackMetrics (metrics/track_metrics.h) is averaged over the RngRuns that
// have it: the time means and the P5s over time of the runs.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/store/track_rows.h"

namespace rlpos {

struct TrackSummary {
  std::string scenario, positioner;
  std::string fidelity;
  int runs = 0;
  // Per kTrackMetrics entry, in its order: the mean over the runs (absent where none has it).
  std::vector<std::optional<double>> means;
};

// Scenarios in the order of `rows`, then held positioners before tracking ones (the order of
// TrackPositionerNames()).
std::vector<TrackSummary> SummarizeTracks(const std::vector<TrackRunRow>& rows);

// A rounded table ("-" for absent); CSV (header TrackSummaryCsvColumns(): scenario, positioner,
// fidelity, runs and each metric's key, unrounded, empty for absent); JSON (null for absent).
std::string FormatTrackSummaryText(const std::vector<TrackSummary>& summary);
// The report's section ("" without track runs): a heading, the table and what it says.
std::string FormatTrackSummaryMarkdown(const std::vector<TrackSummary>& summary);
std::string FormatTrackSummaryCsv(const std::vector<TrackSummary>& summary);
const std::vector<std::string>& TrackSummaryCsvColumns();
nlohmann::json TrackSummaryToJson(const std::vector<TrackSummary>& summary);

}  // namespace rlpos
