#include "common/scenario_generator/generator_options.h"

#include "common/config/config_error.h"

namespace rlpos {

const std::vector<GeneratorStyle>& AllGeneratorStyles() {
  static const std::vector<GeneratorStyle> all{GeneratorStyle::kUrban, GeneratorStyle::kCampus,
                                               GeneratorStyle::kSuburb, GeneratorStyle::kOpen};
  return all;
}

std::string StyleName(GeneratorStyle style) {
  switch (style) {
    case GeneratorStyle::kUrban:
      return "urban";
    case GeneratorStyle::kCampus:
      return "campus";
    case GeneratorStyle::kSuburb:
      return "suburb";
    case GeneratorStyle::kOpen:
      return "open";
  }
  return "open";
}

GeneratorStyle ParseStyle(const std::string& text, const std::string& what) {
  for (GeneratorStyle style : AllGeneratorStyles()) {
    if (StyleName(style) == text)
      return style;
  }
  throw ConfigError(what, "unknown style \"" + text + "\" (urban, campus, suburb or open)");
}

GeneratorStyle ResolvedStyle(const GeneratorOptions& options) {
  if (options.style)
    return *options.style;
  return AllGeneratorStyles()[options.seed % AllGeneratorStyles().size()];
}

int DefaultUeCount(GeneratorStyle style, int uavs) {
  const int base = style == GeneratorStyle::kSuburb ? 8 : 10;
  return base + 4 * (uavs - 1);
}

GeneratorOptions ResolvedOptions(const GeneratorOptions& options) {
  if (options.uavs < 1 || options.uavs > kMaxGeneratedUavs) {
    throw ConfigError("--uavs", std::to_string(options.uavs) +
                                    " UAVs; a generated scenario has 1 to " +
                                    std::to_string(kMaxGeneratedUavs) + " (a Wi-Fi channel each)");
  }
  if (options.ues && (*options.ues < 1 || *options.ues > kMaxGeneratedUes)) {
    throw ConfigError("--ues", std::to_string(*options.ues) +
                                   " UEs; a generated scenario has 1 to " +
                                   std::to_string(kMaxGeneratedUes));
  }
  GeneratorOptions resolved = options;
  resolved.style = ResolvedStyle(options);
  if (!resolved.ues)
    resolved.ues = DefaultUeCount(*resolved.style, resolved.uavs);
  return resolved;
}

}  // namespace rlpos
