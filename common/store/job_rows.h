#pragma once
// How a job's parameters and placement sit in a row of the jobs table, for the store's classes
// and the placement binding (coordinator/scheduling) that read or write them.
#include <optional>
#include <string>

#include "common/campaign/expansion.h"
#include "common/store/store_records.h"

namespace rlpos {

class Statement;

// The typed job columns, in the order ReadParams reads them.
constexpr const char* kParamColumns =
    "kind, scenario, train_seed, fidelity, train_episodes, positioner, rng_run, duration_s, "
    "warmup_s, overrides_json, x, y, z, positions_json, policy_sha256";

// The placement of x, y, z, positions_json starting at `first`: positions_json when set (several
// UAVs), else x, y, z when bound. Throws on a malformed positions_json.
std::optional<Placement> ReadPlacement(const Statement& row, int first);

// Reads kParamColumns starting at `first`; sets `placement` from positions_json or x, y, z.
// Throws StoreError naming `file` for a malformed row.
JobParams ReadParams(const Statement& row, int first, std::optional<Placement>& placement,
                     const std::string& file);

// The columns ReadRunningJob reads, in order.
constexpr const char* kRunningJobColumns =
    "id, campaign_id, COALESCE(worker_id, ''), COALESCE(slot, 0), attempt, started_at, timeout_s";

// A running job's lease from kRunningJobColumns.
RunningJob ReadRunningJob(const Statement& row);

// jobs.positions_json: every UAV's position of a placement of several, NULL for one (x, y, z).
std::optional<std::string> PositionsJson(const Placement& placement);

}  // namespace rlpos
