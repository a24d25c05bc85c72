#pragma once
// summary.md: the one file of a report meant to be read as is (or pasted into an issue): which
// campaign, how far it got, the summary table (and the one per UAV of scenarios with several),
// and a warning when failed jobs leave runs out.
#include <string>
#include <vector>

#include "common/store/optimality_rows.h"
#include "common/store/results_reader.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/uav_summary.h"

namespace rlpos {

std::string FormatReportMarkdown(const CampaignProgress& progress,
                                 const std::vector<PositionerSummary>& summary,
                                 const std::vector<UavSummary>& uavs = {});

// The "Optimality" section: rl's reward against the oracle's, per algorithm and UAV count, and
// the runs below 95 % of the oracle. "" when no scenario has both rl and oracle rewards.
std::string FormatOptimalitySection(const std::vector<OptimalityRow>& rows);

}  // namespace rlpos
