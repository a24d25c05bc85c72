#pragma once
// Shared helpers of the results tests: temporary folders, the shipped campaigns, and the JSON
// that rlpos-sim prints for each kind of job.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/temp_dir.h"

namespace rlpos::testing {

std::string SourcePath(const std::string& relative);  // inside the repository

CampaignSpec MiniSpec();          // campaigns/mini.json
ExpandedCampaign MiniCampaign();  // its jobs, without the result cache
const Job& FindJob(const ExpandedCampaign& campaign, const std::string& key);

// stdout of `rlpos-sim train|position --json` and of `rlpos-sim eval --json`.
nlohmann::json PositionResult(double x, double y, double z);
nlohmann::json EvalResult(std::uint64_t run, double throughput_mbps, double delay_ms);
// Every field of two jobs' params, naming the ones that differ.
::testing::AssertionResult SameParams(const JobParams& a, const JobParams& b);

// The one column of the first row of `sql` on the database file, opened read-only as a user's
// own query would: "<null>" for NULL, "<no row>", or the error message.
std::string QueryOne(const std::string& db_file, const std::string& sql);

// `result` with the position the store bound to the eval job (results of another position are
// refused as implausible).
nlohmann::json AtJobPosition(ResultsReader& store, const std::string& job_id,
                             nlohmann::json result);

// "x,y,z" per UAV, space-separated; "unbound" for none.
std::string FormatPlacement(const std::optional<Placement>& placement);

}  // namespace rlpos::testing
