#include "worker/programs/rlpos_sim/generate_command.h"

#include <iostream>
#include <limits>

#include "common/config/config_error.h"
#include "common/files/atomic_file.h"
#include "common/scenario_generator/generated_mobility.h"
#include "common/scenario_generator/scenario_generator.h"
#include "worker/env/network/scenario_loading.h"
#include "worker/programs/rlpos_sim/commands.h"

namespace rlpos::sim {
namespace {

// A whole number in [lo, hi], digits only (no sign, no spaces); else a ConfigError naming
// `option`.
unsigned long long WholeNumber(const std::string& text, const std::string& option,
                               unsigned long long lo, unsigned long long hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw ConfigError(option, "\"" + text + "\" is not a whole number from " + range);
  unsigned long long value = 0;
  try {
    value = std::stoull(text);
  } catch (const std::out_of_range&) {
    throw ConfigError(option, text + " is out of range (" + range + ")");
  }
  if (value < lo || value > hi)
    throw ConfigError(option, text + " is out of range (" + range + ")");
  return value;
}

GeneratorOptions OptionsOf(const GenerateCommand& g) {
  GeneratorOptions o;
  o.seed = WholeNumber(g.seed, "--seed", 0, std::numeric_limits<std::uint64_t>::max());
  if (!g.style.empty())
    o.style = ParseStyle(g.style, "--style");
  o.uavs = static_cast<int>(WholeNumber(g.uavs, "--uavs", 1, kMaxGeneratedUavs));
  if (!g.ues.empty())
    o.ues = static_cast<int>(WholeNumber(g.ues, "--ues", 1, kMaxGeneratedUes));
  if (!g.mobility.empty())
    o.mobility = ParseGeneratedMobility(g.mobility, "--mobility");
  return o;
}

}  // namespace

void AddGenerate(CLI::App& app, GenerateCommand& g) {
  g.command = app.add_subcommand("generate", "Write a scenario drawn from a seed");
  g.command->add_option("--seed", g.seed, "Seed (a whole number); same seed, same bytes")
      ->required();
  g.command->add_option("--style", g.style,
                        "urban|campus|suburb|open (default: the seed's, seed mod 4 in this order)");
  g.command->add_option("--uavs", g.uavs, "UAVs, 1-6 (default 1; 4-6 on 80 MHz channels)");
  g.command->add_option("--ues", g.ues, "UEs, 1-100 (default: the style's, 4 more per extra UAV)");
  g.command->add_option("--mobility", g.mobility,
                        "random_waypoint|gauss_markov|crowd: every UE moves so (default: static)");
  g.command->add_option("--out", g.out, "Scenario file to write (default: stdout)");
}

int RunGenerate(const GenerateCommand& g) {
  const GeneratorOptions options = OptionsOf(g);
  GeneratedScenario generated;
  try {
    generated = GenerateScenario(options);
  } catch (const GeneratorError& e) {
    throw std::runtime_error(std::string("cannot generate: ") + e.what());
  }
  // The ns-3 side of validation (TypeIds, attributes, channels), as rlpos-sim validate does.
  CheckScenarioAgainstNs3(generated.scenario);
  if (g.out.empty()) {
    std::cout << generated.json_text << std::flush;
    return kExitOk;
  }
  try {
    WriteFileAtomically(g.out, generated.json_text);
  } catch (const std::runtime_error& e) {
    throw ConfigError("--out", e.what());
  }
  return kExitOk;
}

}  // namespace rlpos::sim
