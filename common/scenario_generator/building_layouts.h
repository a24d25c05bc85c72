#pragma once
// The venue and buildings of each style, drawn from the distributions documented in
// docs/scenarios.md (Generated scenarios). All lengths are whole metres.
#include <optional>
#include <string>
#include <vector>

#include "common/scenario/scenario.h"
#include "common/scenario_generator/generator_options.h"
#include "common/scenario_generator/portable_random.h"

namespace rlpos {

struct Layout {
  Venue venue;
  std::vector<BuildingSpec> buildings;
  std::string summary;  // one phrase for the scenario's description
};

// Draws a venue and its buildings in `style`; nullopt when this draw could not place them
// (the caller draws again).
std::optional<Layout> DrawLayout(GeneratorStyle style, PortableRandom& random);

}  // namespace rlpos
