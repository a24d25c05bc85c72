#pragma once
// What a job computes, as a hash, for the result cache: every ns-3 and agent run is seeded, so
// two jobs with the same content give the same result and one's result can serve the other.
// The content is the build (rlpos version), the sha256 of the campaign's scenario document
// (canonical JSON, before overrides), every field of JobParams that changes what a job of its
// kind runs (declared in job/job_fields.h, which the build holds to JobParams) and, for an eval,
// its placement. Not the campaign, the label or an eval's train seed: those only say where a
// job comes from, so an rl eval and an offset eval at the same position share content.
#include <optional>
#include <string>

#include "common/job/job.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// Everything but an eval's placement (bound later, when its dependency succeeds).
std::string JobContentBase(const JobParams& params, const std::string& scenario_sha256,
                           const std::string& build);

// The cache key: `base` for a train or position job; for an eval, `base` with its placement
// (each UAV's position to the micrometre), or nothing while the placement is unknown.
std::optional<std::string> JobContentKey(const std::string& base, JobKind kind,
                                         const std::optional<Placement>& placement);

}  // namespace rlpos
