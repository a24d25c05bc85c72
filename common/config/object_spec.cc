#include "common/config/object_spec.h"

#include "common/config/config_error.h"
#include "common/config/object_reader.h"

namespace rlpos {

ObjectSpec ReadObjectSpec(const nlohmann::json& v, const std::string& path) {
  ObjectReader r(v, path);
  ObjectSpec spec;
  spec.type = r.String("type", "");
  if (spec.type.empty())
    throw ConfigError(r.PathOf("type"), "is required (an ns-3 TypeId name)");
  if (const nlohmann::json* attributes = r.Child("attributes")) {
    if (!attributes->is_object()) {
      throw ConfigError(r.PathOf("attributes"), "expected an object, got " + TypeName(*attributes));
    }
    for (auto it = attributes->begin(); it != attributes->end(); ++it) {
      const std::string attribute_path = JoinPath(r.PathOf("attributes"), it.key());
      if (it->is_object()) {
        ReadObjectSpec(*it, attribute_path);  // nested spec: validate its shape now
      } else if (it->is_number()) {
        CheckedNumber(*it, attribute_path, {});
      } else if (!it->is_string() && !it->is_boolean()) {
        throw ConfigError(attribute_path, "expected a number, string, boolean or {\"type\": ...}");
      }
    }
    spec.attributes = *attributes;
  }
  r.Finish();
  return spec;
}

nlohmann::json ObjectSpecJson(const ObjectSpec& spec) {
  return {{"type", spec.type}, {"attributes", spec.attributes}};
}

}  // namespace rlpos
