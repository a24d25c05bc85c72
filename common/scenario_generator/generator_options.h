#pragma once
// What `rlpos-sim generate` is asked for: a seed, a style, how many UAVs and UEs, how they move.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"

namespace rlpos {

// urban: a block grid of tall buildings with streets; campus: clusters of mid-rise buildings
// with open space between; suburb: sparse low houses; open: free space.
enum class GeneratorStyle { kUrban, kCampus, kSuburb, kOpen };

// The UAVs a generated scenario can hold, each on a channel of its own: up to three on 160 MHz
// channels (50, 114, 163), four to six on 80 MHz channels (42, 58, 106, 122, 138, 155).
constexpr int kMaxGeneratedUavs = 6;
// The most UEs a generated scenario holds (placement stays quick, as does every evaluation).
constexpr int kMaxGeneratedUes = 100;

struct GeneratorOptions {
  std::uint64_t seed = 0;
  std::optional<GeneratorStyle> style;  // unset: kAllStyles()[seed % 4]
  int uavs = 1;
  std::optional<int> ues;  // unset: DefaultUeCount(style, uavs)
  // unset: static UEs (and the same bytes as before --mobility existed)
  std::optional<MobilityModel> mobility;
};

// The styles in their documented order (urban, campus, suburb, open).
const std::vector<GeneratorStyle>& AllGeneratorStyles();
std::string StyleName(GeneratorStyle style);
// "urban" -> kUrban; anything else is a ConfigError naming `what` and the styles.
GeneratorStyle ParseStyle(const std::string& text, const std::string& what);

// The style the options select (the given one, or the one the seed selects).
GeneratorStyle ResolvedStyle(const GeneratorOptions& options);
// UEs when --ues is not given: the style's base (urban 10, campus 10, suburb 8, open 10) plus 4
// per UAV beyond the first.
int DefaultUeCount(GeneratorStyle style, int uavs);
// The options with style and UE count filled in; a UAV or UE count out of range is a
// ConfigError naming --uavs or --ues.
GeneratorOptions ResolvedOptions(const GeneratorOptions& options);

}  // namespace rlpos
