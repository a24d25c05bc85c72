#pragma once
// rlpos-sim generate --seed N [--style urban|campus|suburb|open] [--uavs K] [--ues M]
// [--mobility random_waypoint|gauss_markov|crowd] [--out FILE]: a scenario drawn from a seed
// (common/scenario_generator), checked by the parser and against ns-3, written whole to FILE or to
// stdout.
#include <CLI/CLI.hpp>
#include <string>

namespace rlpos::sim {

struct GenerateCommand {
  CLI::App* command = nullptr;
  // As typed: parsed here, so that every bad value gets the same one-line error.
  std::string seed, style, uavs = "1", ues, mobility, out;
};

// Adds `generate` to `app`.
void AddGenerate(CLI::App& app, GenerateCommand& generate);
// Generates, validates and writes; bad options throw ConfigError naming the option.
int RunGenerate(const GenerateCommand& generate);

}  // namespace rlpos::sim
