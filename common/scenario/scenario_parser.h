#pragma once
// Scenario JSON -> Scenario, with every field validated. Errors are ConfigError naming the JSON
// path (e.g. "/ues/2/position/0"). Checks that need ns-3 (TypeIds, attributes, channel
// numbers) are done by the worker's ns-3 validation on top of this.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/config/config_error.h"
#include "common/scenario/scenario.h"

namespace rlpos {

// Parses a JSON document; malformed JSON becomes a ConfigError with the line and column.
nlohmann::json ParseJsonText(const std::string& text);

// Reads and parses a file; a missing or unreadable file is a ConfigError too.
nlohmann::json ReadJsonFile(const std::string& file);

// Applies "path=value" overrides. Paths are dotted ("wifi.mode", "ues.3.demand.mbps") or JSON
// pointers ("/wifi/mode"); the value is JSON if it parses as JSON, else a string.
void ApplyOverrides(nlohmann::json& document, const std::vector<std::string>& overrides);

// The JSON pointer an override's path names ("wifi.width" and "/wifi/width" give "/wifi/width");
// "" when the text has no "path=".
std::string OverridePointer(const std::string& override_text);

// A scenario error as the user should read it: when the error's path lies at or inside a path
// that one of `overrides` set (the last such one), a ConfigError that names that override
// ("--set wifi.width=77" with "/wifi/width: must be ..."), since the value came from the command
// line or a campaign's "set", not from the file. Otherwise `error` itself.
ConfigError BlameOverride(const ConfigError& error, const std::vector<std::string>& overrides);

// The agent algorithms, in report order, and the overrides that select one: its
// agent.algorithm and the action space it acts on (sac: continuous; dqn, ppo: discrete).
const std::vector<std::string>& AllAlgorithms();
std::vector<std::string> AlgorithmOverrides(const std::string& algorithm);

// Full model, validated (structure, ranges, geometry). Missing fields take the paper's defaults.
Scenario ParseScenario(const nlohmann::json& document);

// The model back to JSON, every field explicit (the effective configuration of a run).
nlohmann::json ToJson(const Scenario& scenario);

}  // namespace rlpos
