#pragma once
// A job's settings reach its scenario one way: as overrides of the scenario document, applied by
// EffectiveScenarioDocument (wire/job_order.h) in one order: the campaign scenario's "set" and
// a train job's algorithm overrides (JobParams::overrides, in order), then the settings the
// job's own fields fix (job_fields.h: train seed, fidelity and episodes, RngRun, duration,
// warm-up). An override that gives one of those another value is a contradiction, refused when
// the campaign is read and again by the worker: the order above never has to decide one.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "common/job/job.h"

namespace rlpos {

// One setting a field of the job fixes: the field's name and the override that sets it.
struct JobSetting {
  const char* field;         // "fidelity"
  ScenarioOverride setting;  // {"/env/fidelity", "analytic"}
};

// The settings of `params`' fields for its kind, in declaration order; an unset field sets
// nothing (the scenario's own value stands).
std::vector<JobSetting> JobSettings(const JobParams& params);

// An override of `overrides` that sets the path of a setting of `settings` (or an object that
// holds it) to another value.
struct Contradiction {
  std::size_t override_index, setting_index;
};
std::optional<Contradiction> FindContradiction(const std::vector<ScenarioOverride>& overrides,
                                               const std::vector<ScenarioOverride>& settings);

}  // namespace rlpos
