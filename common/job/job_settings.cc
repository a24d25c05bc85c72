#include "common/job/job_settings.h"

#include "common/job/job_fields.h"
#include "common/scenario/number_text.h"
#include "common/scenario/scenario_parser.h"

namespace rlpos {
namespace {

using nlohmann::json;

// A field's value as override text, as ApplyOverrides reads it back: numbers exactly, a text
// as itself.
std::string SettingText(const json& value) {
  if (value.is_number_float())
    return FormatNumber(value.get<double>());
  if (value.is_string())
    return value.get<std::string>();
  return value.dump();
}

// ApplyOverrides' reading of a path: a JSON pointer, or dotted.
json::json_pointer PointerOf(std::string path) {
  if (path.empty() || path[0] != '/') {
    for (auto& c : path)
      c = c == '.' ? '/' : c;
    path = "/" + path;
  }
  return json::json_pointer(path);
}

// What `o` alone makes of an empty document: the values it gives, at the paths it gives them.
std::optional<json> Probe(const ScenarioOverride& o) {
  json probe = json::object();
  try {
    ApplyOverrides(probe, {ToString(o)});
  } catch (const std::exception&) {
    return std::nullopt;  // not settable: the scenario's validation says why
  }
  return probe;
}

}  // namespace

std::vector<JobSetting> JobSettings(const JobParams& params) {
  std::vector<JobSetting> out;
  ForEachField(params, [&](const auto& field, const auto& value) {
    if (!field.setting || !Includes(field.kinds, params.kind))
      return;
    const json v = FieldJson(value);
    if (!v.is_null())
      out.push_back({field.name, {field.setting, SettingText(v)}});
  });
  return out;
}

std::optional<Contradiction> FindContradiction(const std::vector<ScenarioOverride>& overrides,
                                               const std::vector<ScenarioOverride>& settings) {
  if (overrides.empty() || settings.empty())
    return std::nullopt;
  std::vector<json::json_pointer> pointers;
  pointers.reserve(settings.size());
  for (const auto& s : settings)
    pointers.push_back(PointerOf(s.path));
  std::vector<std::optional<json>> wanted(settings.size());  // read when an override touches it
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    const std::optional<json> probe = Probe(overrides[i]);
    if (!probe)
      continue;
    for (std::size_t j = 0; j < settings.size(); ++j) {
      if (!probe->contains(pointers[j]))
        continue;
      if (!wanted[j]) {
        const std::optional<json> setting = Probe(settings[j]);
        wanted[j] = setting && setting->contains(pointers[j]) ? setting->at(pointers[j]) : json();
      }
      if (probe->at(pointers[j]) != *wanted[j])
        return Contradiction{i, j};
    }
  }
  return std::nullopt;
}

}  // namespace rlpos
