#include "worker/programs/rlpos_sim/import_command.h"

#include <filesystem>
#include <iostream>

#include "common/config/config_error.h"
#include "common/files/atomic_file.h"
#include "common/scenario/scenario_parser.h"
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
  import.command = app.add_subcommand("import", "Turn another tool's config into a scenario");
  import.command->add_option("--from", import.from, "The config's format: rlpos3")->required();
  import.command->add_option("config", config_file, "The config (RLpos-3: config/input.json)")
      ->required();
  import.command->add_option("--out", import.out, "Write the scenario here (default: stdout)");
}

int RunImport(const ImportCommand& import, const std::string& config_file) {
  if (import.from != "rlpos3")
    throw ConfigError("--from", "unknown format \"" + import.from + "\" (known: rlpos3)");
  const nlohmann::json config = ReadJsonFile(config_file);
  const std::string name = std::filesystem::path(config_file).stem().string();
  const ImportResult result = ImportRlpos3(config, name);
  CheckAgainstNs3(result.scenario);
  for (const ImportWarning& w : result.warnings) {
    std::cerr << "rlpos-sim: warning: " << config_file << ": " << w.path << ": " << w.message
              << "\n";
  }
  const std::string text = ToJson(result.scenario).dump(2) + "\n";
  if (import.out.empty())
    std::cout << text << std::flush;
  else
    WriteFileAtomically(import.out, text);
  return kExitOk;
}

}  // namespace rlpos::sim
