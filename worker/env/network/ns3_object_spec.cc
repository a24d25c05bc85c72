#include "worker/env/network/ns3_object_spec.h"

#include <ns3/object-factory.h>
#include <ns3/pointer.h>
#include <ns3/string.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "common/config/config_error.h"
#include "common/config/did_you_mean.h"
#include "common/config/object_reader.h"

namespace rlpos {
namespace {

std::vector<std::string> AttributeNames(ns3::TypeId tid) {
  std::vector<std::string> names;
  for (ns3::TypeId t = tid;; t = t.GetParent()) {
    for (std::size_t i = 0; i < t.GetAttributeN(); ++i)
      names.push_back(t.GetAttribute(i).name);
    if (t == t.GetParent())
      break;
  }
  return names;
}

ns3::TypeId LookUpType(const std::string& name, const std::string& path, ns3::TypeId base) {
  ns3::TypeId tid;
  if (!ns3::TypeId::LookupByNameFailSafe(name, &tid)) {
    std::vector<std::string> candidates;
    for (uint16_t i = 0; i < ns3::TypeId::GetRegisteredN(); ++i) {
      ns3::TypeId t = ns3::TypeId::GetRegistered(i);
      if (t.IsChildOf(base))
        candidates.push_back(t.GetName());
    }
    std::string message = "unknown ns-3 TypeId \"" + name + "\"";
    const std::string hint = ClosestMatch(name, candidates);
    if (!hint.empty())
      message += "; did you mean \"" + hint + "\"?";
    throw ConfigError(path, message);
  }
  if (tid != base && !tid.IsChildOf(base)) {
    throw ConfigError(path, "\"" + name + "\" is not a " + base.GetName());
  }
  if (!tid.HasConstructor()) {
    throw ConfigError(path, "\"" + name + "\" cannot be created (abstract type)");
  }
  return tid;
}

}  // namespace

std::string AttributeString(const nlohmann::json& value) {
  if (value.is_string())
    return value.get<std::string>();
  if (value.is_boolean())
    return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer())
    return std::to_string(value.get<long long>());
  std::ostringstream out;
  out.precision(17);
  out << value.get<double>();
  return out.str();
}

ns3::Ptr<ns3::Object> CreateFromSpec(const ObjectSpec& spec, const std::string& path,
                                     ns3::TypeId base, const std::string& tracked_attribute,
                                     std::set<const ns3::Object*>* explicitly_set) {
  const ns3::TypeId tid = LookUpType(spec.type, JoinPath(path, "type"), base);
  ns3::ObjectFactory factory;
  factory.SetTypeId(tid);
  bool tracked = false;
  for (auto it = spec.attributes.begin(); it != spec.attributes.end(); ++it) {
    const std::string attribute_path = JoinPath(JoinPath(path, "attributes"), it.key());
    ns3::TypeId::AttributeInformation info;
    if (!tid.LookupAttributeByName(it.key(), &info)) {
      std::string message = spec.type + " has no attribute \"" + it.key() + "\"";
      const std::string hint = ClosestMatch(it.key(), AttributeNames(tid));
      if (!hint.empty())
        message += "; did you mean \"" + hint + "\"?";
      throw ConfigError(attribute_path, message);
    }
    if (!(info.flags & ns3::TypeId::ATTR_CONSTRUCT)) {
      throw ConfigError(attribute_path, "attribute \"" + it.key() + "\" cannot be set");
    }
    if (it->is_object()) {
      const auto* pointer =
          dynamic_cast<const ns3::PointerChecker*>(ns3::PeekPointer(info.checker));
      if (!pointer) {
        throw ConfigError(attribute_path, "attribute \"" + it.key() +
                                              "\" is not an object pointer; give a scalar value");
      }
      ObjectSpec nested;
      nested.type = it->value("type", "");
      nested.attributes = it->value("attributes", nlohmann::json::object());
      factory.Set(it.key(), ns3::PointerValue(CreateFromSpec(nested, attribute_path,
                                                             pointer->GetPointeeTypeId(),
                                                             tracked_attribute, explicitly_set)));
      continue;
    }
    const std::string text = AttributeString(*it);
    ns3::Ptr<ns3::AttributeValue> valid = info.checker->CreateValidValue(ns3::StringValue(text));
    if (!valid) {
      throw ConfigError(attribute_path, "invalid value \"" + text + "\" for attribute \"" +
                                            it.key() + "\" (expects " +
                                            info.checker->GetUnderlyingTypeInformation() + ")");
    }
    factory.Set(it.key(), *valid);
    tracked = tracked || it.key() == tracked_attribute;
  }
  ns3::Ptr<ns3::Object> object = factory.Create();
  if (tracked && explicitly_set)
    explicitly_set->insert(ns3::PeekPointer(object));
  return object;
}

void VisitObjectTree(ns3::Ptr<ns3::Object> root,
                     const std::function<void(ns3::Ptr<ns3::Object>)>& visit) {
  if (!root)
    return;
  visit(root);
  const ns3::TypeId tid = root->GetInstanceTypeId();
  ns3::TypeId::AttributeInformation info;
  for (const auto& name : AttributeNames(tid)) {
    tid.LookupAttributeByName(name, &info);
    if (!dynamic_cast<const ns3::PointerChecker*>(ns3::PeekPointer(info.checker)))
      continue;
    if (!(info.flags & ns3::TypeId::ATTR_GET))
      continue;
    ns3::PointerValue child;
    root->GetAttribute(name, child);
    VisitObjectTree(child.Get<ns3::Object>(), visit);
  }
}

int SetAttributeInTree(ns3::Ptr<ns3::Object> root, const std::string& attribute,
                       const ns3::AttributeValue& value, const std::set<const ns3::Object*>& skip) {
  int count = 0;
  VisitObjectTree(root, [&](ns3::Ptr<ns3::Object> object) {
    ns3::TypeId::AttributeInformation info;
    if (!skip.count(ns3::PeekPointer(object)) &&
        object->GetInstanceTypeId().LookupAttributeByName(attribute, &info)) {
      object->SetAttribute(attribute, value);
      ++count;
    }
  });
  return count;
}

std::mutex& Ns3ObjectsMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace rlpos
