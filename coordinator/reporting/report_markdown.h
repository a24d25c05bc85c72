#pragma once
// summary.md: the one file of a report meant to be read as is (or pasted into an issue): which
// campaign, how far it got, the summary table (and the one per UAV of scenarios with several),
// and a warning when failed jobs leave runs out.
#include <string>
#include <vector>

#include "common/store/results_reader.h"
#include "coordinator/reporting/campaign_summary.h"
#include "coordinator/reporting/uav_summary.h"

namespace rlpos {

std::string FormatReportMarkdown(const CampaignProgress& progress,
                                 const std::vector<PositionerSummary>& summary,
                                 const std::vector<UavSummary>& uavs = {});

}  // namespace rlpos
