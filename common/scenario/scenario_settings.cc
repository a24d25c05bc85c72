#include "common/scenario/scenario_settings.h"

#include <string>

namespace rlpos {

const SettingsTable<Scenario>& ScenarioSettings() {
  static const SettingsTable<Scenario> table{
      "scenario",
      "",
      "The document's top level: these keys; its lists of buildings, UEs and UAVs, each element "
      "as the building, ue and uav tables; and the sections below (venue, wifi, traffic, "
      "simulation, env, agent).",
      {{"name", &Scenario::name, NoRange(), "the scenario's label, which reports go by"},
       {"description", &Scenario::description, NoRange(), "free text"},
       {"propagation", &Scenario::propagation, NoRange(),
        "any installed ns-3 PropagationLossModel, with its attributes; default our obstacle-aware "
        "model with ITU-R P.1411's LoS/NLoS pair"},
       {"log_level",
        &Scenario::log_level,
        NoRange(),
        "what the run logs to stderr",
        "",
        {"error", "warning", "info", "debug"}}}};
  return table;
}

Scenario ScenarioDefaults() {
  Scenario s;
  s.name = "scenario";
  s.propagation = DefaultPropagation();
  return s;
}

std::vector<SettingRow> ScenarioListRows() {
  // {key, type, default, default's text, values, unit, doc, bounds, choices}
  return {{"buildings",
           "[{building}, ...]",
           "[]",
           "[]",
           "",
           "",
           "the buildings, each as the building table",
           {},
           {}},
          {"ues",
           "[{ue}, ...]",
           "[]",
           "required",
           "",
           "",
           "the UEs (at least one), each as the ue table",
           {},
           {}},
          {"uav", "{uav}", "{}", "{}", "", "", "one UAV, as the uav table", {}, {}},
          {"uavs",
           "[{uav}, ...]",
           "[]",
           "one uav",
           "",
           "",
           "several UAVs instead of uav (at most " + std::to_string(kMaxUavs) +
               "), each as the uav table (docs/several-uavs.md)",
           {},
           {}}};
}

}  // namespace rlpos
