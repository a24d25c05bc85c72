#pragma once
// The report's maps: one per scenario of the campaign, with every positioner's placement in one
// picture, drawn by `rlpos-sim render` (the coordinator side has no ns-3 and no Cairo). Nothing
// read from the database becomes a path or a shell string: the scenario and the rl flight are
// written to files of a temporary folder the report owns, the placements travel as argv entries,
// and each map is named after the scenario's place in the campaign (map_1.png, ...).
#include <string>
#include <vector>

#include "common/store/results_reader.h"

namespace rlpos {

struct ScenarioMap {
  std::string scenario;             // its name in the campaign
  std::string file;                 // "map_<k>.png" in the report folder
  std::vector<std::string> labels;  // the placements drawn, in report order
  bool flight = false;              // the rl flight (trajectory.csv) drawn
};

struct ScenarioMapsOutcome {
  std::vector<ScenarioMap> maps;
  std::vector<std::string> files;     // paths written
  std::vector<std::string> warnings;  // why a map is missing, or its flight
};

// A label's placement is that of its eval with the lowest RngRun: every run of a label
// evaluates the one placement its position or train job gave. A scenario with no eval yet is
// drawn at its baseline. `render_program` is rlpos-sim; a failure is a warning, not an error.
ScenarioMapsOutcome RenderScenarioMaps(ResultsReader& store, const std::string& campaign_id,
                                       const std::string& render_program,
                                       const std::string& out_dir);

// The "## Maps" section of summary.md.
std::string FormatMapsMarkdown(const std::vector<ScenarioMap>& maps);

// rlpos-sim beside the running program's folder.
std::string DefaultRenderProgram(const std::string& exe_dir);

}  // namespace rlpos
