#pragma once
// rlpos-sim import --from rlpos3 CONFIG.json [--out FILE]: another tool's scenario as ours
// (common/scenario_import), checked as `validate` checks a scenario (ns-3 included) before
// anything is written; a warning on stderr names each field that was not carried over.
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos::sim {

struct ImportCommand {
  CLI::App* command = nullptr;
  std::string from;
  std::string out;  // empty: stdout
};

// Adds `import` to `app`; its CONFIG argument goes to `config_file` (the file errors name).
void AddImport(CLI::App& app, ImportCommand& import, std::string& config_file);
// Converts, checks, prints the warnings, writes the scenario. Bad input throws ConfigError.
int RunImport(const ImportCommand& import, const std::string& config_file);

}  // namespace rlpos::sim
