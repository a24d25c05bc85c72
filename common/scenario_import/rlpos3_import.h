#pragma once
// RLpos-3's config/input.json -> a Scenario. RLpos-3 (the paper's own ns-3/ns3-gym code) keeps
// its scenario, its ns-3 settings and its agent's hyperparameters in one JSON file; this turns
// it into a scenario of ours that validates, and names every field it could not carry over.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// A field of the source that was not carried over as it was: its JSON path in the source and
// why (dropped, rounded, or defaulted differently).
struct ImportWarning {
  std::string path;
  std::string message;
};

struct ImportResult {
  Scenario scenario;
  std::vector<ImportWarning> warnings;  // in a fixed order: the same config, the same list
};

// Converts a parsed RLpos-3 config. `name` labels the scenario (e.g. the file's stem). The
// result has passed ParseScenario (structure, ranges, geometry). Bad input throws ConfigError
// naming the source's JSON path (e.g. "/ns3Sim/defaultValues/Buildings/2/BuildingPosition").
ImportResult ImportRlpos3(const nlohmann::json& config, const std::string& name);

// The source path that a path of the scenario came from ("/ues/3/position" ->
// "/ns3Sim/defaultValues/UENodes/3/positionVector"), for errors found after the conversion
// (ns-3's checks); a path with no source is returned as it is.
std::string Rlpos3SourcePath(const std::string& scenario_path);

}  // namespace rlpos
