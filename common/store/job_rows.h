#pragma once
// How a job's parameters and placement sit in a row of the jobs table, for the store's classes
// and the placement binding (coordinator/scheduling) that read or write them.
#include <optional>
#include <string>

#include "common/campaign/expansion.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_records.h"

namespace rlpos {

// A placement's columns x, y, z, positions_json in a statement that selects them.
struct PlacementColumns {
  explicit PlacementColumns(const Statement& select);
  ResultColumn x, y, z, positions_json;
};

// The placement of the row: positions_json when set (several UAVs), else x, y, z when bound.
// Throws on a malformed positions_json.
std::optional<Placement> ReadPlacement(const Statement& row, const PlacementColumns& columns);

// The typed job columns, which ReadParams reads (by name: their order is free).
constexpr const char* kParamColumns =
    "kind, scenario, train_seed, fidelity, train_episodes, positioner, rng_run, duration_s, "
    "warmup_s, overrides_json, x, y, z, positions_json, policy_sha256";

// kParamColumns in a statement that selects them.
struct ParamColumns {
  explicit ParamColumns(const Statement& select);
  ResultColumn kind, scenario, train_seed, fidelity, train_episodes, positioner, rng_run,
      duration_s, warmup_s, overrides_json, policy_sha256;
  PlacementColumns placement;
};

// Reads kParamColumns; sets `placement` from positions_json or x, y, z. Throws StoreError naming
// `file` for a malformed row.
JobParams ReadParams(const Statement& row, const ParamColumns& columns,
                     std::optional<Placement>& placement, const std::string& file);

// The columns ReadRunningJob reads.
constexpr const char* kRunningJobColumns =
    "id, campaign_id, COALESCE(worker_id, '') AS worker_id, COALESCE(slot, 0) AS slot, attempt, "
    "started_at, timeout_s";

// kRunningJobColumns in a statement that selects them.
struct RunningJobColumns {
  explicit RunningJobColumns(const Statement& select);
  ResultColumn id, campaign_id, worker_id, slot, attempt, started_at, timeout_s;
};

// A running job's lease from kRunningJobColumns.
RunningJob ReadRunningJob(const Statement& row, const RunningJobColumns& columns);

// jobs.positions_json: every UAV's position of a placement of several, NULL for one (x, y, z).
std::optional<std::string> PositionsJson(const Placement& placement);

}  // namespace rlpos
