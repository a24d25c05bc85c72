#include "worker/learning/training/scenario_draw.h"

#include <random>

#include "common/config/config_error.h"
#include "common/scenario_generator/scenario_generator.h"

namespace rlpos {
namespace {

int ParseCount(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || text.front() == '+' || text.front() == '-')
    throw ConfigError(what, "\"" + text + "\" is not a count");
  return value;
}

// A generator seed's own draws (style, UAVs, UEs): std::mt19937_64 and modulo, the same on every
// platform.
int Pick(std::mt19937_64& rng, const CountRange& range) {
  const auto span = static_cast<std::uint64_t>(range.max - range.min + 1);
  return range.min + static_cast<int>(rng() % span);
}

// Seeds tried after one the generator gives up on (rare: kMaxGeneratorAttempts draws each).
constexpr int kSeedsTried = 8;

}  // namespace

CountRange ParseCountRange(const std::string& text, int lowest, int highest,
                           const std::string& what) {
  CountRange range;
  const std::size_t dash = text.find('-');
  if (dash == std::string::npos) {
    range.min = range.max = ParseCount(text, what);
  } else {
    range.min = ParseCount(text.substr(0, dash), what);
    range.max = ParseCount(text.substr(dash + 1), what);
  }
  if (range.min > range.max)
    throw ConfigError(what, "\"" + text + "\": the first count is larger than the second");
  if (range.min < lowest || range.max > highest) {
    throw ConfigError(what, "\"" + text + "\": expected counts from " + std::to_string(lowest) +
                                " to " + std::to_string(highest));
  }
  return range;
}

std::string FormatCountRange(const CountRange& range) {
  return range.min == range.max ? std::to_string(range.min)
                                : std::to_string(range.min) + "-" + std::to_string(range.max);
}

ScenarioDraw::ScenarioDraw(GeneratedDistribution distribution, const Scenario& settings,
                           std::uint64_t seed)
    : distribution_(std::move(distribution)),
      env_(settings.env),
      agent_(settings.agent),
      seed_(seed) {
  if (distribution_.styles.empty())
    throw ConfigError("--generated", "names no style");
  if (seed_ > kMaxTrainingSeed)
    throw ConfigError("--seed",
                      "at most " + std::to_string(kMaxTrainingSeed) + " with --generated");
}

ScenarioDraw::ScenarioDraw(std::vector<Scenario> set, std::vector<std::string> names,
                           const Scenario& settings, std::uint64_t seed)
    : set_(std::move(set)),
      names_(std::move(names)),
      env_(settings.env),
      agent_(settings.agent),
      seed_(seed) {
  if (set_->empty())
    throw ConfigError("--scenarios", "holds no scenario");
}

Scenario ScenarioDraw::WithSettings(Scenario s) const {
  s.env = env_;
  s.agent = agent_;
  return s;
}

DrawnScenario ScenarioDraw::Generate(std::uint64_t generator_seed) const {
  for (int tried = 0;; ++tried) {
    const std::uint64_t seed = generator_seed + static_cast<std::uint64_t>(tried);
    std::mt19937_64 rng(seed);
    GeneratorOptions options;
    options.seed = seed;
    options.style = distribution_.styles[rng() % distribution_.styles.size()];
    options.uavs = Pick(rng, distribution_.uavs);
    if (distribution_.ues)
      options.ues = Pick(rng, *distribution_.ues);
    try {
      GeneratedScenario g = GenerateScenario(options);
      return {WithSettings(std::move(g.scenario)), "generated seed " + std::to_string(seed), seed};
    } catch (const GeneratorError&) {
      if (tried + 1 == kSeedsTried)
        throw;
    }
  }
}

DrawnScenario ScenarioDraw::Training(std::uint64_t k) const {
  if (!set_)
    return Generate(FirstTrainingSeed() + k);
  std::mt19937_64 rng(FirstTrainingSeed() + k);
  const std::size_t i = rng() % set_->size();
  return {WithSettings((*set_)[i]), names_[i], 0};
}

DrawnScenario ScenarioDraw::Validation(std::uint64_t i) const {
  if (!set_)
    return Generate(kValidationSeedBase + i);
  const std::size_t j = i % set_->size();
  return {WithSettings((*set_)[j]), names_[j], 0};
}

}  // namespace rlpos
