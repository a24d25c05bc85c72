#pragma once
// One attempt of one job as the coordinator orders it from a worker: the typed job, where the
// UAVs go, the campaign's scenario document and the attempt's limits. The IDL type
// JobAssignment carries exactly these fields (and the worker it is for).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/job/job.h"
#include "common/scenario/scenario.h"
#include "common/wire/policy_bundle.h"

namespace rlpos {

struct JobOrder {
  std::string job_id, campaign_id;
  int attempt = 1;
  double timeout_s = 0;
  JobParams params;
  // eval: one position per UAV (the scenario's order), bound when the dependency succeeds
  std::optional<Placement> placement;
  std::string scenario_document;  // the campaign scenario's JSON, before any override
  // position "rl": the named policy's files, whose sha256 is params.policy_sha256
  std::optional<PolicyBundle> policy;
};

// What a validated order runs.
struct CheckedOrder {
  nlohmann::json scenario;  // the document with the job's settings and overrides applied
  Scenario parsed;          // ParseScenario of it
};

// An override's path holds only plain keys and indices ([A-Za-z0-9._@+-], '/' or '.' between
// them), its value is bounded. Throws std::invalid_argument.
void CheckOverride(const ScenarioOverride& o);

// The scenario document a job runs, its settings' one way in (job/job_settings.h): the
// campaign's document, then the job's overrides in order (the campaign scenario's "set", a train
// job's algorithm), then the settings of the job's own fields (agent.seed, env.fidelity,
// agent.train_episodes, simulation.run, .duration, .warmup). Throws ConfigError.
nlohmann::json EffectiveScenarioDocument(const nlohmann::json& document, const JobParams& params);

// Checks every field of an order that came over the network, and the scenario it describes
// (parsed and validated as rlpos-sim would; an eval's placement has a position per UAV, each
// inside the venue and outside every building; no override contradicts a setting of the job's
// fields; a named policy's position job carries its bundle, CheckPolicyBundle-clean and of the
// job's policy_sha256, and no other job carries one). `max_timeout_s` is the worker's cap. Throws
// std::invalid_argument naming the field.
CheckedOrder CheckJobOrder(const JobOrder& order, double max_timeout_s);

}  // namespace rlpos
