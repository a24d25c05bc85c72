#pragma once
// How `run`, `status` and the campaign page show a campaign's progress: a bar, counts, and an ETA
// from the rate at which jobs have finished so far (rough: jobs differ in length, train jobs
// first).
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/number_text.h"  // FormatDuration
#include "common/store/store_records.h"

namespace rlpos {

// Remaining seconds, or nothing before the first job finished (or when all are done).
std::optional<double> EstimateRemainingSeconds(const CampaignProgress& progress,
                                               const CampaignTiming& timing, double now);

// "[########............]  40/100  running 2  failed 1  ETA 3m20s"
std::string ProgressLine(const CampaignProgress& progress, std::optional<double> eta_s,
                         int bar_width = 24);

// True when no job of the campaign can still change (nothing pending, ready or running).
bool IsSettled(const CampaignProgress& progress);

// The `status` text: one block per campaign, then the workers.
std::string FormatStatus(const std::vector<CampaignProgress>& campaigns,
                         const std::vector<CampaignTiming>& timings,
                         const std::vector<WorkerRecord>& workers, double now);

}  // namespace rlpos
