#pragma once
// The scenario document's top level, declared once (scenario_settings.cc): its labels, log level
// and propagation, read and written like any section's settings; and its lists of objects, read
// element by element with the building, ue and uav tables, as rows of its docs table.
#include <vector>

#include "common/config/setting_rows.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// The top level's settings ("name", "description", "propagation", "log_level"), at path "".
const SettingsTable<Scenario>& ScenarioSettings();

// A scenario holding the top level's defaults, which differ from Scenario's own initialisers
// (name "scenario", the default propagation): where ParseScenario starts from.
Scenario ScenarioDefaults();

// The docs rows of the top level's lists (buildings, ues, uav, uavs), which the parser reads
// element by element: so that every key a document may hold is listed.
std::vector<SettingRow> ScenarioListRows();

}  // namespace rlpos
