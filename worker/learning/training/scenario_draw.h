#pragma once
// The scenarios a policy for any scenario trains on: one drawn per training episode, either a
// fresh generated one (rlpos-sim train --generated) or one of a user's set (--scenarios DIR).
// Each carries the training's env and agent settings, so that every draw has the same spaces.
//
// Generator seeds. Draw k of training seed S uses generator seed
//   kTrainingSeedBase + S * kDrawsPerSeed + k,
// and validation scenario i uses kValidationSeedBase + i. Both ranges start far above the seeds
// of scripts/generate_scenario_set.sh (train 10000-13999, held-out 90000-93999), so a policy
// never trains or selects its checkpoints on a held-out scenario.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "common/scenario_generator/generator_options.h"

namespace rlpos {

constexpr std::uint64_t kTrainingSeedBase = 1000000000;   // 1e9
constexpr std::uint64_t kDrawsPerSeed = 100000000;        // 1e8 draws per training seed
constexpr std::uint64_t kValidationSeedBase = 500000000;  // 5e8
constexpr std::uint64_t kMaxTrainingSeed = 1000000;       // keeps every seed below 2**63

// An inclusive range of counts, "3" or "1-3".
struct CountRange {
  int min = 1;
  int max = 1;
};
// "3" -> {3, 3}, "1-3" -> {1, 3}; anything else, or a range outside [lowest, highest], is a
// ConfigError naming `what`.
CountRange ParseCountRange(const std::string& text, int lowest, int highest,
                           const std::string& what);
std::string FormatCountRange(const CountRange& range);

// What a generated draw may be: styles, UAV and UE counts.
struct GeneratedDistribution {
  std::vector<GeneratorStyle> styles;  // at least one
  CountRange uavs;                     // 1 .. kMaxGeneratedUavs
  std::optional<CountRange> ues;       // unset: the generator's default for the style and UAVs
};

// One draw: the scenario and where it came from (the generator seed, or the file).
struct DrawnScenario {
  Scenario scenario;
  std::string origin;  // "generated seed N" or the file's name
  std::uint64_t generator_seed = 0;
};

class ScenarioDraw {
 public:
  // Generated scenarios of `distribution`; each draw gets `settings`' env and agent.
  ScenarioDraw(GeneratedDistribution distribution, const Scenario& settings, std::uint64_t seed);
  // The scenarios of a user's set, drawn uniformly from the seed; each gets `settings`' env and
  // agent. ConfigError for an empty set.
  ScenarioDraw(std::vector<Scenario> set, std::vector<std::string> names, const Scenario& settings,
               std::uint64_t seed);

  // Training draw k (k < kDrawsPerSeed): the same k, the same scenario.
  DrawnScenario Training(std::uint64_t k) const;
  // Validation scenario i, never a training draw: generated from the validation range, or for
  // a user's set its i-th scenario (mod the set's size).
  DrawnScenario Validation(std::uint64_t i) const;

  bool Generated() const { return !set_.has_value(); }
  std::uint64_t FirstTrainingSeed() const { return kTrainingSeedBase + seed_ * kDrawsPerSeed; }
  const GeneratedDistribution& Distribution() const { return distribution_; }

 private:
  DrawnScenario Generate(std::uint64_t generator_seed) const;
  Scenario WithSettings(Scenario s) const;

  GeneratedDistribution distribution_;
  std::optional<std::vector<Scenario>> set_;
  std::vector<std::string> names_;
  EnvSpec env_;
  AgentSpec agent_;
  std::uint64_t seed_;
};

}  // namespace rlpos
