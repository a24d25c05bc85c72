#include "common/wire/job_order.h"

#include <cmath>
#include <stdexcept>

#include "common/config/config_error.h"
#include "common/hash/sha256.h"
#include "common/job/job_settings.h"
#include "common/scenario/names.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_checks.h"
#include "common/scenario/scenario_parser.h"
#include "common/wire/identifiers.h"
#include "common/wire/json_text.h"
#include "common/wire/limits.h"

namespace rlpos {

static_assert(kMaxUavs == wire::kMaxUavPositions, "an order carries a position per UAV");

namespace {

using nlohmann::json;

[[noreturn]] void Bad(const std::string& field, const std::string& problem) {
  throw std::invalid_argument(field + ": " + problem);
}

void CheckDuration(const std::optional<double>& v, const char* field, bool zero_ok) {
  if (!v)
    return;
  // A day of simulated time is far past any experiment; NaN fails every comparison.
  if (!(std::isfinite(*v) && (zero_ok ? *v >= 0 : *v > 0) && *v <= 86400)) {
    Bad(field,
        "must be in " + std::string(zero_ok ? "[0" : "(0") + ", 86400] s, got " + FormatNumber(*v));
  }
}

// A track job: a positioner that flies no trained-per-scenario policy (rl names one), a
// fidelity, an RngRun and a duration (track's command line needs both).
void CheckTrackParams(const JobParams& p) {
  if (p.positioner == "rl") {
    if (!IsSha256Hex(p.policy_sha256))
      Bad("policy_sha256", "an rl track job needs its policy's sha256");
  } else if (!IsOneOf(p.positioner, kPlacingPositioners) &&
             !IsOneOf(p.positioner, kTrackingPositioners)) {
    Bad("positioner", "must be " + Alternatives(kPlacingPositioners) + ", " +
                          Alternatives(kTrackingPositioners) + " or rl, got \"" +
                          wire::Printable(p.positioner) + "\"");
  }
  if (!IsOneOf(p.fidelity, kFidelities)) {
    Bad("fidelity",
        "must be " + Alternatives(kFidelities) + ", got \"" + wire::Printable(p.fidelity) + "\"");
  }
  if (!p.rng_run || *p.rng_run < 1 || *p.rng_run > 4294967295ULL)
    Bad("rng_run", "a track job needs one in 1..4294967295");
  if (!p.duration_s)
    Bad("duration_s", "a track job needs one");
}

void CheckParams(const JobParams& p) {
  if (!wire::IsSafeName(p.scenario, wire::kMaxNameLength)) {
    Bad("scenario", "not a scenario name: \"" + wire::Printable(p.scenario) + "\"");
  }
  switch (p.kind) {
    case JobKind::kTrain:
      if (!p.train_seed)
        Bad("train_seed", "a train job needs one");
      if (!IsOneOf(p.fidelity, kFidelities)) {
        Bad("fidelity", "must be " + Alternatives(kFidelities) + ", got \"" +
                            wire::Printable(p.fidelity) + "\"");
      }
      if (p.train_episodes && (*p.train_episodes < 1 || *p.train_episodes > 1000000)) {
        Bad("train_episodes", "must be in 1..1000000");
      }
      break;
    case JobKind::kPosition:
      if (p.positioner == "rl") {
        if (!IsSha256Hex(p.policy_sha256))
          Bad("policy_sha256", "an rl position job needs its policy's sha256");
        break;
      }
      if (!IsOneOf(p.positioner, kPlacingPositioners)) {
        Bad("positioner", "must be " + Alternatives(kPlacingPositioners) + " or rl, got \"" +
                              wire::Printable(p.positioner) + "\"");
      }
      break;
    case JobKind::kEval:
      if (!p.rng_run || *p.rng_run < 1 || *p.rng_run > 4294967295ULL) {
        Bad("rng_run", "an eval job needs one in 1..4294967295");
      }
      break;
    case JobKind::kTrack:
      CheckTrackParams(p);
      break;
    default:
      Bad("kind", "unknown job kind " + std::to_string(static_cast<int>(p.kind)));
  }
  const bool flies_policy =
      (p.kind == JobKind::kPosition || p.kind == JobKind::kTrack) && p.positioner == "rl";
  if (!flies_policy && !p.policy_sha256.empty())
    Bad("policy_sha256", "only an rl position or track job has one");
  CheckDuration(p.duration_s, "duration_s", false);
  CheckDuration(p.warmup_s, "warmup_s", true);
  if (p.overrides.size() > wire::kMaxOverrides)
    Bad("overrides", "too many");
  for (const auto& o : p.overrides)
    CheckOverride(o);
  // The campaign refuses these; an order that has one was not made from a campaign we read.
  const std::vector<JobSetting> settings = JobSettings(p);
  std::vector<ScenarioOverride> fixed;
  for (const auto& s : settings)
    fixed.push_back(s.setting);
  if (const auto c = FindContradiction(p.overrides, fixed)) {
    Bad("overrides[" + std::to_string(c->override_index) + "]",
        "\"" + wire::Printable(ToString(p.overrides[c->override_index])) +
            "\" contradicts the job's " + settings[c->setting_index].field + " (" +
            ToString(fixed[c->setting_index]) + ")");
  }
}

}  // namespace

void CheckOverride(const ScenarioOverride& o) {
  // Dotted paths or JSON pointers of plain keys and indices: nothing else reaches a scenario.
  std::string path = o.path;
  if (!path.empty() && path[0] == '/')
    path = path.substr(1);
  for (auto& c : path)
    c = c == '.' ? '/' : c;
  if (!wire::IsSafePath(path, wire::kMaxOverridePath)) {
    Bad("overrides", "not a scenario path: \"" + wire::Printable(o.path) + "\"");
  }
  if (o.value.size() > wire::kMaxOverrideValue)
    Bad("overrides", "value too long");
  if (wire::JsonNestingDepth(o.value) > wire::kMaxJsonDepth)
    Bad("overrides", "value too deep");
}

json EffectiveScenarioDocument(const json& document, const JobParams& params) {
  std::vector<std::string> settings;
  for (const auto& o : params.overrides)
    settings.push_back(ToString(o));
  for (const auto& s : JobSettings(params))
    settings.push_back(ToString(s.setting));
  json effective = document;
  ApplyOverrides(effective, settings);
  return effective;
}

CheckedOrder CheckJobOrder(const JobOrder& order, double max_timeout_s) {
  if (!wire::IsSafePath(order.job_id, wire::kMaxIdLength)) {
    Bad("job_id", "not a job id: \"" + wire::Printable(order.job_id) + "\"");
  }
  if (!wire::IsSafeName(order.campaign_id, wire::kMaxCampaignIdLength) ||
      order.job_id.compare(0, order.campaign_id.size() + 1, order.campaign_id + "/") != 0) {
    Bad("campaign_id", "\"" + wire::Printable(order.campaign_id) + "\" does not own job " +
                           wire::Printable(order.job_id));
  }
  if (order.attempt < 1 || order.attempt > wire::kMaxAttempt) {
    Bad("attempt", "must be in 1.." + std::to_string(wire::kMaxAttempt));
  }
  if (!(std::isfinite(order.timeout_s) && order.timeout_s > 0 &&
        order.timeout_s <= max_timeout_s)) {
    Bad("timeout_s", "must be in (0, " + FormatNumber(max_timeout_s) + "] s, got " +
                         FormatNumber(order.timeout_s));
  }
  CheckParams(order.params);
  if (order.params.policy_sha256.empty() != !order.policy)
    Bad("policy",
        order.policy ? "only an rl position or track job carries one" : "the job's is missing");
  if (order.policy) {
    if (const std::string problem = CheckPolicyBundle(*order.policy); !problem.empty())
      Bad("policy", problem);
    if (order.policy->sha256 != order.params.policy_sha256)
      Bad("policy", "not the job's policy " + order.params.policy_sha256);
  }
  CheckedOrder checked;
  const json document = wire::ParseBoundedJson(order.scenario_document, wire::kMaxScenarioDocument,
                                               "scenario_document");
  try {
    checked.scenario = EffectiveScenarioDocument(document, order.params);
    checked.parsed = ParseScenario(checked.scenario);
  } catch (const ConfigError& e) {
    Bad("scenario_document", e.describe());
  }
  if (checked.parsed.name != order.params.scenario) {
    Bad("scenario", "the document's scenario is \"" + wire::Printable(checked.parsed.name) +
                        "\", the job's \"" + order.params.scenario + "\"");
  }
  if (order.params.kind == JobKind::kEval) {
    if (!order.placement)
      Bad("positions", "an eval job needs one per UAV");
    const std::size_t uavs = checked.parsed.uavs.size();
    if (order.placement->size() != uavs) {
      Bad("positions", std::to_string(order.placement->size()) + " given, the scenario has " +
                           std::to_string(uavs) + " UAV" + (uavs == 1 ? "" : "s"));
    }
    const Venue& v = checked.parsed.venue;
    for (std::size_t i = 0; i < uavs; ++i) {
      const Vec3& p = (*order.placement)[i];
      const std::string field = "positions[" + std::to_string(i) + "]";
      if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.x >= 0 &&
            p.x <= v.width && p.y >= 0 && p.y <= v.depth && p.z >= 0 && p.z <= v.height)) {
        Bad(field, FormatPosition(p) + " is outside the venue");
      }
      if (BuildingContaining(checked.parsed, p) >= 0)
        Bad(field, FormatPosition(p) + " is inside a building");
    }
  } else if (order.placement) {
    Bad("positions", "only an eval job has them");
  }
  return checked;
}

}  // namespace rlpos
