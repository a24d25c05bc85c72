#pragma once
// Schema 2 stored a job as an rlpos-sim command line (argv_json). Migration 3 reads the typed
// fields out of it once; nothing else ever parses a command line.
#include <optional>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

struct LegacyJobFields {
  std::optional<std::string> fidelity, positioner;
  std::optional<double> duration_s;
  std::string overrides_json = "[]";  // [[path, value], ...]: the --set arguments in order
  std::optional<Vec3> position;       // a bound --position (not the "{position}" placeholder)
};

// Throws std::invalid_argument for text that is not a JSON array of strings.
LegacyJobFields LegacyJobFieldsFromArgv(const std::string& argv_json);

}  // namespace rlpos
