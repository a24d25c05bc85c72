#pragma once
// rlpos-sim import --from rlpos3 CONFIG.json [--out FILE]: another tool's scenario as ours; and
// import --from osm|geojson FILE --center LAT,LON --size WxD (or --bbox): a real place, its
// buildings as footprints (common/scenario_import). Either is checked as `validate` checks a
// scenario (ns-3 included) before anything is written; warnings go to stderr.
#include <CLI/CLI.hpp>
#include <string>

#include "common/scenario_import/place_options.h"

namespace rlpos::sim {

struct ImportCommand {
  CLI::App* command = nullptr;
  std::string from;
  std::string out;  // empty: stdout
  // --from osm|geojson: the venue as given (parsed by place_options.h), and the rest.
  std::string center, size, bbox;
  PlaceImportOptions place;
};

// Adds `import` to `app`; its CONFIG argument goes to `config_file` (the file errors name).
void AddImport(CLI::App& app, ImportCommand& import, std::string& config_file);
// Converts, checks, prints the warnings, writes the scenario. Bad input throws ConfigError.
int RunImport(const ImportCommand& import, const std::string& config_file);

}  // namespace rlpos::sim
