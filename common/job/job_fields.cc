#include "common/job/job_fields.h"

namespace rlpos {

using nlohmann::json;

json FieldJson(JobKind kind) {
  return ToString(kind);
}

json FieldJson(const std::string& text) {
  return text.empty() ? json() : json(text);
}

json FieldJson(const std::optional<std::uint64_t>& value) {
  return value ? json(*value) : json();
}

json FieldJson(const std::optional<int>& value) {
  return value ? json(*value) : json();
}

json FieldJson(const std::optional<double>& value) {
  return value ? json(*value) : json();
}

json FieldJson(const std::vector<ScenarioOverride>& overrides) {
  json out = json::array();
  for (const auto& o : overrides)
    out.push_back({o.path, o.value});
  return out;
}

}  // namespace rlpos
