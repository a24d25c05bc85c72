#include "worker/programs/rlpos_sim/import_command.h"

#include <filesystem>
#include <iostream>

#include "common/config/config_error.h"
#include "common/files/atomic_file.h"
#include "common/scenario/scenario_parser.h"
#include "common/scenario_import/place_import.h"
#include "common/scenario_import/rlpos3_import.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {
namespace {

// ns-3's checks (TypeIds, attributes, the channel number), as `validate` runs them.
void CheckAgainstNs3(const Scenario& scenario) {
  try {
    CheckScenarioAgainstNs3(scenario);
  } catch (const ConfigError& e) {
    throw ConfigError(Rlpos3SourcePath(e.path()),
                      e.problem() + " (as the scenario's " + e.path() + ")");
  }
}

}  // namespace

void AddImport(CLI::App& app, ImportCommand& import, std::string& config_file) {
  import.command = app.add_subcommand(
      "import",
      "Turn another tool's config, or a real place (OpenStreetMap, GeoJSON), into a "
      "scenario");
  auto* c = import.command;
  c->add_option("--from", import.from, "The file's format: rlpos3, osm or geojson")->required();
  c->add_option("config", config_file,
                "The file: RLpos-3's config/input.json, an .osm/.osm.pbf extract, or a GeoJSON "
                "FeatureCollection of buildings")
      ->required();
  c->add_option("--out", import.out, "Write the scenario here (default: stdout)");
  const std::string place = "Real places (osm, geojson)";
  c->add_option("--center", import.center, "The venue's centre, LAT,LON in degrees (with --size)")
      ->group(place);
  c->add_option("--size", import.size, "The venue's size WxD in metres (east-west x north-south)")
      ->group(place);
  c->add_option("--bbox", import.bbox,
                "The venue as MINLON,MINLAT,MAXLON,MAXLAT in degrees (instead of --center and "
                "--size)")
      ->group(place);
  c->add_option("--ues", import.place.ues, "UEs, drawn outdoors along the streets")->group(place);
  c->add_option("--ue-groups", import.place.ue_groups,
                "Groups the UEs gather in (default 0: each drawn on its own)")
      ->group(place);
  c->add_option("--uavs", import.place.uavs, "UAVs (default 1)")->group(place);
  c->add_option("--seed", import.place.seed, "Seed of the UE draw (default 0)")->group(place);
  c->add_option("--level-height", import.place.heights.level_height,
                "Metres per building:levels when a building has no height (default 3)")
      ->group(place);
  c->add_option("--default-height", import.place.heights.default_height,
                "Height of a building with neither height nor levels, m (default 10)")
      ->group(place);
  c->add_option("--name", import.place.name,
                "The scenario's name (default: osm-<file> or geojson-<file>)")
      ->group(place);
}

namespace {

int WriteScenario(const ImportCommand& import, const std::string& text) {
  if (import.out.empty())
    std::cout << text << std::flush;
  else
    WriteFileAtomically(import.out, text);
  return kExitOk;
}

int RunRlpos3Import(const ImportCommand& import, const std::string& config_file) {
  const nlohmann::json config = ReadJsonFile(config_file);
  const std::string name = std::filesystem::path(config_file).stem().string();
  const ImportResult result = ImportRlpos3(config, name);
  CheckAgainstNs3(result.scenario);
  for (const ImportWarning& w : result.warnings) {
    std::cerr << "rlpos-sim: warning: " << config_file << ": " << w.path << ": " << w.message
              << "\n";
  }
  return WriteScenario(import, ToJson(result.scenario).dump(2) + "\n");
}

int RunPlaceImport(const ImportCommand& import, const std::string& file) {
  PlaceImportOptions options = import.place;
  options.file = file;
  options.format = ParsePlaceFormat(import.from);
  if (!import.center.empty())
    options.center = ParsePlaceCenter(import.center);
  if (!import.size.empty())
    options.size = ParseVenueSize(import.size);
  if (!import.bbox.empty())
    options.bbox = ParsePlaceBbox(import.bbox);
  // Errors name the option, or the element of the file (main prefixes the file's name).
  const PlaceImportResult result = ImportPlace(options);
  const Scenario scenario = ParseScenario(result.document);
  CheckScenarioAgainstNs3(scenario);
  for (const ImportWarning& w : result.warnings)
    std::cerr << "rlpos-sim: warning: " << file << ": " << w.path << ": " << w.message << "\n";
  std::cerr << "rlpos-sim: import: " << PlaceSummaryLine(result.summary) << "\n";
  return WriteScenario(import, result.json_text);
}

}  // namespace

int RunImport(const ImportCommand& import, const std::string& config_file) {
  if (import.from == "rlpos3")
    return RunRlpos3Import(import, config_file);
  if (import.from == "osm" || import.from == "geojson")
    return RunPlaceImport(import, config_file);
  throw ConfigError("--from",
                    "unknown format \"" + import.from + "\" (known: rlpos3, osm, geojson)");
}

}  // namespace rlpos::sim
