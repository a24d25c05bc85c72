#pragma once
// rlpos-sim generate's engine: a scenario drawn from a seed, in one of four styles, valid by
// construction and checked anyway. Same options, same bytes, on every platform (integer draws
// from std::mt19937_64, lengths on a half-metre grid; see portable_random.h).
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/scenario/scenario.h"
#include "common/scenario_generator/generator_options.h"

namespace rlpos {

// Draws before giving up on a seed: each draw that fails (a placement that does not fit, a
// scenario that fails the checks, a baseline that sees every UE) is followed by the next.
constexpr int kMaxGeneratorAttempts = 100;

struct GeneratedScenario {
  GeneratorOptions options;    // resolved: style and UE count filled in
  std::string json_text;       // the document, as written (ends with a newline)
  Scenario scenario;           // the document parsed back (what a user's run loads)
  int attempts = 1;            // draws it took (1: the first one was kept)
  int hidden_at_baseline = 0;  // UEs whose links to every baseline UAV are blocked
};

// No valid scenario within kMaxGeneratorAttempts draws; the message names the seed and style.
class GeneratorError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The scenario of `options`. Its document parses and passes the scenario checks, no UE or UAV is
// inside a building, and where the style has buildings at least one UE is hidden from every
// baseline UAV (NLoS at the baseline). Throws ConfigError for options out of range,
// GeneratorError when no draw of the first `max_attempts` met the rules.
GeneratedScenario GenerateScenario(const GeneratorOptions& options,
                                   int max_attempts = kMaxGeneratorAttempts);

// The command line that reproduces `options` (resolved), for the description.
std::string GenerateCommandLine(const GeneratorOptions& options);

}  // namespace rlpos
