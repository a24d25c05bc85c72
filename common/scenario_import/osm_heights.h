#pragma once
// A building's height from its tags, as OpenStreetMap's 3-D buildings read them: `height` (the
// top above the ground), else `building:levels` x the level height plus `roof:height`, else a
// default (for a part that starts above it: its roof, or one level, above its bottom); its
// bottom from `min_height`, else `building:min_level` x the level height, else the ground. A
// value that is not a number falls back to the next source, with a warning.
#include <optional>
#include <string>
#include <vector>

#include "common/scenario_import/place_data.h"

namespace rlpos {

// The tallest building and the most levels the import believes; above that a value is taken
// for a typing error and falls back like text.
constexpr double kMaxBuildingHeight = 1000.0;
constexpr double kMaxLevels = 200.0;

// A length as OpenStreetMap writes it, in metres: "12", "12.5", "12 m", "12.5m", "12 metres",
// "40 ft", "40 feet", "40'", "40'6\"" (feet and inches). nullopt for anything else ("tall",
// "12;15", "12,5", "-3").
std::optional<double> ParseOsmLength(const std::string& text);
// A number of levels ("5", "2.5"); nullopt when it is not a non-negative number.
std::optional<double> ParseOsmLevels(const std::string& text);

enum class HeightSource { kHeight, kLevels, kDefault };

struct HeightRules {
  double level_height = 3.0;     // m per building:levels / building:min_level
  double default_height = 10.0;  // m, with neither height nor building:levels
};

struct ResolvedHeight {
  double height = 0;      // the top (m above the ground), to the centimetre
  double min_height = 0;  // the bottom; 0 stands on the ground
  int floors = 1;         // building:levels less building:min_level, else from the height
  HeightSource source = HeightSource::kDefault;
  int bad_values = 0;  // tags that fell back (each also a warning)
};

// The height of `feature`; each tag that is not a usable number adds a warning naming the
// feature's source.
ResolvedHeight ResolveHeight(const PlaceFeature& feature, const HeightRules& rules,
                             std::vector<ImportWarning>& warnings);

}  // namespace rlpos
