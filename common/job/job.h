#pragma once
// One unit of work of a campaign, as data. Jobs form a small DAG: an eval of the RL position (or
// of positions 1-5 around it) depends on the train job that finds it; an eval of the baseline,
// centroid or oracle position depends on the position job that gives it. What a job runs is its
// typed fields: only the worker turns them into a process (worker/daemon/sim_command.h).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/job/position_rule.h"

namespace rlpos {

// kTrack: a run in which the UEs walk and the UAVs follow a positioner (rlpos-sim track); it
// depends on no job.
enum class JobKind { kTrain, kPosition, kEval, kTrack };
// Every kind, in the order a campaign's ready jobs are scheduled.
inline constexpr std::array<JobKind, 4> kJobKinds{JobKind::kTrain, JobKind::kPosition,
                                                  JobKind::kEval, JobKind::kTrack};

const char* ToString(JobKind kind);  // "train" | "position" | "eval" | "track"
// Throws std::invalid_argument on anything else.
JobKind ParseJobKind(const std::string& text);

// One "set" entry of a campaign scenario: `path` as ApplyOverrides takes it ("wifi.mode",
// "/ues/0/demand"), `value` JSON text or a bare string.
struct ScenarioOverride {
  std::string path, value;
  bool operator==(const ScenarioOverride& o) const { return path == o.path && value == o.value; }
};

// Splits "path=value"; throws std::invalid_argument when there is no '=' or no path.
ScenarioOverride ParseOverride(const std::string& text);
std::string ToString(const ScenarioOverride& o);  // "path=value"

// What one job runs: the fields a worker needs besides the scenario document and the attempt.
struct JobParams {
  JobKind kind = JobKind::kEval;
  std::string scenario;                     // the scenario's name in its campaign
  std::optional<std::uint64_t> train_seed;  // train jobs (and the evals that depend on them)
  std::string fidelity;                     // train, track: "analytic" | "packet"
  std::optional<int> train_episodes;        // train: unset = the scenario's
  std::string positioner;                   // position: "baseline" | "centroid" | "oracle" | "rl";
                                            // track: those but rl, "oracle-track", "centroid-track"
  std::string policy_sha256;                // position "rl": the named policy's bundle hash
  std::optional<std::uint64_t> rng_run;     // eval, track
  std::optional<double> duration_s, warmup_s;  // unset = the scenario's simulation settings
  std::vector<ScenarioOverride> overrides;     // the campaign scenario's "set", in order
};

struct Job {
  std::string id;              // "<campaign id>/<key>"
  std::string key;             // train/<scenario>/seed<N> | position/<scenario>/<positioner> |
                               // eval/<scenario>/<label>/run<R> | track/<scenario>/<label>/run<R>
  std::string label;           // baseline|centroid|oracle|rl|offset1..5, "@seed<N>" for later seeds
  std::string depends_on;      // id of the job whose position this one needs, "" for none
  PositionRule position_rule;  // eval jobs: how their position follows from the dependency's
  JobParams params;
  std::string content_base;  // JobContentBase (campaign/job_content.h): for the result cache
};

}  // namespace rlpos
