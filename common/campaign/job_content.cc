#include "common/campaign/job_content.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "common/hash/sha256.h"
#include "common/job/job_fields.h"

namespace rlpos {
namespace {

// Fields declared after results were first cached: left out of the content while unset, so
// that the jobs without them keep the keys their cached results have.
bool LeftOutWhenUnset(const char* field) {
  return std::string(field) == "policy_sha256";
}

}  // namespace

std::string JobContentBase(const JobParams& p, const std::string& scenario_sha256,
                           const std::string& build) {
  // The keys are the fields' declared names (the JSON object sorts them): the same content keeps
  // the key it had when these fields were listed here by hand.
  nlohmann::json content = {{"content", 1}, {"build", build}, {"scenario_sha256", scenario_sha256}};
  ForEachField(p, [&](const auto& field, const auto& value) {
    if (!Includes(field.kinds, p.kind))
      return;
    nlohmann::json v = FieldJson(value);
    if (!(v.is_null() && LeftOutWhenUnset(field.name)))
      content[field.name] = std::move(v);
  });
  return Sha256Hex(content.dump());
}

std::optional<std::string> JobContentKey(const std::string& base, JobKind kind,
                                         const std::optional<Placement>& placement) {
  if (base.empty())
    return std::nullopt;
  if (kind != JobKind::kEval)
    return base;
  if (!placement || placement->empty())
    return std::nullopt;
  // Whole micrometres: positions reached by different arithmetic (an rl position, an offset
  // around another) that agree to far below a simulation's resolution count as one.
  const auto um = [](double v) { return std::to_string(std::llround(v * 1e6)); };
  // One UAV: "|x,y,z", as before several UAVs existed, so cached single-UAV results still serve.
  std::string text = base;
  char separator = '|';
  for (const Vec3& p : *placement) {
    text += separator + um(p.x) + "," + um(p.y) + "," + um(p.z);
    separator = ';';
  }
  return Sha256Hex(text);
}

}  // namespace rlpos
