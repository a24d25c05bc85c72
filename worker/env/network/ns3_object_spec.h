#pragma once
// ObjectSpec ({"type": TypeId name, "attributes": {...}}) -> a configured ns-3 object, with every
// name and value checked first, so that a bad spec is a ConfigError naming its JSON path instead
// of an ns-3 fatal error.
#include <ns3/object.h>
#include <ns3/type-id.h>

#include <functional>
#include <mutex>
#include <set>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// Creates the object (nested specs become the values of pointer attributes). `base` is the type
// the object must derive from (e.g. PropagationLossModel). `explicitly_set` receives the objects
// whose spec set `tracked_attribute` (used to tell defaults from user choices).
ns3::Ptr<ns3::Object> CreateFromSpec(const ObjectSpec& spec, const std::string& path,
                                     ns3::TypeId base, const std::string& tracked_attribute = "",
                                     std::set<const ns3::Object*>* explicitly_set = nullptr);

// Calls `visit` on `root` and on every object reachable from it through pointer attributes.
void VisitObjectTree(ns3::Ptr<ns3::Object> root,
                     const std::function<void(ns3::Ptr<ns3::Object>)>& visit);

// Sets `attribute` on `root` and every object reachable from it through pointer attributes,
// except the objects in `skip`. Returns how many objects were set.
int SetAttributeInTree(ns3::Ptr<ns3::Object> root, const std::string& attribute,
                       const ns3::AttributeValue& value, const std::set<const ns3::Object*>& skip);

// Creating ns-3 objects registers TypeIds, attributes and Wi-Fi modes in process-wide tables on
// first use: code that creates ns-3 objects outside the one packet-level network (the analytic
// model, the scenario checks) holds this lock meanwhile, so that threads take turns.
std::mutex& Ns3ObjectsMutex();

// JSON scalar -> the string form ns-3 attribute checkers parse.
std::string AttributeString(const nlohmann::json& value);

}  // namespace rlpos
