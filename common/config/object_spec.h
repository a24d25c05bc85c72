#pragma once
// An ns-3 object chosen the ns-3 way: a TypeId name and attribute values. An attribute value is a
// JSON scalar (converted to the attribute's string form) or a nested {"type", "attributes"} spec
// for pointer attributes. Plain data: the worker turns it into the ns-3 object.
#include <nlohmann/json.hpp>
#include <string>

namespace rlpos {

struct ObjectSpec {
  std::string type;
  nlohmann::json attributes = nlohmann::json::object();
};

// Reads {"type", "attributes"} at `path`; the attributes' shape is checked, nested specs too.
ObjectSpec ReadObjectSpec(const nlohmann::json& v, const std::string& path);
nlohmann::json ObjectSpecJson(const ObjectSpec& spec);

}  // namespace rlpos
