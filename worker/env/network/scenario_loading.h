#pragma once
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// FILE's document with the --set overrides applied: what its author stated, no defaults.
nlohmann::json ScenarioDocument(const std::string& file, const std::vector<std::string>& overrides);

// Reads FILE, applies --set overrides, parses and validates (structure, geometry and the ns-3
// side: TypeIds, attributes, Wi-Fi channel). Throws ConfigError.
Scenario LoadScenario(const std::string& file, const std::vector<std::string>& overrides);

// The ns-3 checks alone (no simulation is built).
void CheckScenarioAgainstNs3(const Scenario& scenario);

// "x,y,z" -> Vec3; throws ConfigError naming `what`.
Vec3 ParsePosition(const std::string& text, const std::string& what);

// A position the UAV may take in this scenario: inside the venue and outside every building.
void CheckUavPosition(const Scenario& scenario, const Vec3& p, const std::string& what);

// One "x,y,z" per UAV of the scenario, in its order, each a position a UAV may take, the UAVs
// kMinUavSeparation apart. Throws ConfigError naming `what`.
Placement ParsePlacement(const Scenario& scenario, const std::vector<std::string>& texts,
                         const std::string& what);

}  // namespace rlpos
