#pragma once
// One unit of work of a campaign: a child `rlpos-sim` process. Jobs form a small DAG: an eval
// of the RL position (or of positions 1-5 around it) depends on the train job that finds it; an
// eval of the baseline, centroid or oracle position depends on the position job that gives it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "campaign/position_rule.h"

namespace rlpos {

enum class JobKind { kTrain, kPosition, kEval };

const char* ToString(JobKind kind);  // "train" | "position" | "eval"
// Throws std::invalid_argument on anything else.
JobKind ParseJobKind(const std::string& text);

struct Job {
  std::string id;          // "<campaign id>/<key>"
  std::string key;         // train/<scenario>/seed<N> | position/<scenario>/<positioner> |
                           // eval/<scenario>/<label>/run<R>
  JobKind kind = JobKind::kEval;
  std::string scenario;    // the scenario's name
  std::string label;       // baseline|centroid|oracle|rl|offset1..5, "@seed<N>" for later seeds
  std::optional<std::uint64_t> rng_run;  // eval jobs
  std::optional<std::uint64_t> train_seed;  // train jobs and the evals that depend on them
  std::string depends_on;  // id of the job whose position this one needs, "" for none
  PositionRule position;   // eval jobs: how their position follows from the dependency's
  std::vector<std::string> argv;  // rlpos-sim command line with placeholders (job_argv.h)
};

}  // namespace rlpos
