#include "common/scenario_import/rlpos3_import.h"

#include <algorithm>

#include "common/config/config_error.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_import/rlpos3_parts.h"

namespace rlpos {
namespace {

// The venue's height limit holds the zone's ceiling and everything RLpos-3 placed (its format
// has no height limit of its own: a building may rise above the UAV's Zmax).
double VenueHeight(const Scenario& s, double zmax) {
  double height = zmax;
  for (const auto& b : s.buildings)
    height = std::max(height, b.height);
  for (const auto& ue : s.ues)
    height = std::max(height, ue.position.z);
  return height;
}

// Our parser's checks (ranges, geometry) on the result; an error names the source's field.
Scenario Validated(const Scenario& s) {
  try {
    return ParseScenario(ToJson(s));
  } catch (const ConfigError& e) {
    throw ConfigError(Rlpos3SourcePath(e.path()),
                      e.problem() + " (as the scenario's " + e.path() + ")");
  }
}

}  // namespace

ImportResult ImportRlpos3(const nlohmann::json& config, const std::string& name) {
  ImportResult result;
  Scenario s;
  s.name = name;
  s.description = "Imported from the RLpos-3 config " + name;
  s.propagation = DefaultPropagation();  // RLpos-3 sets its loss models in code, not in the config
  Rlpos3Object root(config, "", result.warnings);
  root.NotCarried("StartScript",
                  "how RLpos-3 starts its agent and ns-3; rlpos-sim train and "
                  "eval start themselves");
  Rlpos3Object gym = root.Object("Gym", "an object with venueSize");
  const Rlpos3Frame frame = ReadGym(gym, s);
  Rlpos3Object ns3 = root.Object("ns3Sim", "an object with defaultValues");
  ns3.NotCarried("logLevels", "RLpos-3's log switches; here log_level (stays \"warning\")");
  Rlpos3Object config_sim = ns3.OptionalObject("configSim");
  ReadConfigSim(config_sim, s);
  Rlpos3Object defaults = ns3.Object("defaultValues", "UENodes, UAVNodes, Buildings, radio");
  ReadRadio(defaults, s);
  ReadNodes(defaults, frame, s);
  defaults.Finish();
  ns3.Finish();
  Rlpos3Object agent = root.OptionalObject("Agent");
  ReadAgent(agent, s);
  root.Finish();
  s.venue.height = VenueHeight(s, frame.zmax);
  result.scenario = Validated(s);
  return result;
}

}  // namespace rlpos
