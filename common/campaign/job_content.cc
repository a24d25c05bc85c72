#include "common/campaign/job_content.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "common/hash/sha256.h"

namespace rlpos {

std::string JobContentBase(const JobParams& p, const std::string& scenario_sha256,
                           const std::string& build) {
  nlohmann::json overrides = nlohmann::json::array();
  for (const auto& o : p.overrides)
    overrides.push_back({o.path, o.value});
  nlohmann::json content = {{"content", 1},
                            {"build", build},
                            {"kind", ToString(p.kind)},
                            {"scenario_sha256", scenario_sha256},
                            {"overrides", overrides},
                            {"duration_s", nullptr},
                            {"warmup_s", nullptr}};
  if (p.duration_s)
    content["duration_s"] = *p.duration_s;
  if (p.warmup_s)
    content["warmup_s"] = *p.warmup_s;
  switch (p.kind) {
    case JobKind::kTrain:
      content["train_seed"] = p.train_seed.value_or(0);
      content["fidelity"] = p.fidelity;
      content["train_episodes"] = p.train_episodes ? nlohmann::json(*p.train_episodes) : nullptr;
      break;
    case JobKind::kPosition:
      content["positioner"] = p.positioner;
      break;
    case JobKind::kEval:
      content["rng_run"] = p.rng_run.value_or(0);
      break;
  }
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
