#pragma once
// The document of a generated scenario: the scenario's JSON as common/scenario writes it (ToJson,
// the one writer of its fields), laid out as the shipped scenarios are: their key order, only
// what the generator chose (the env and agent sections and static UEs' mobility are left out, so
// the defaults apply), and whole numbers written as integers.
#include <nlohmann/json.hpp>
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// The propagation the generator gives a scenario: the shipped scenarios' ITU-R P.1411 pair, with
// their over-rooftop parameters where there are buildings, its defaults in free space (as A).
ObjectSpec GeneratedPropagation(bool has_buildings);

// The JSON text (two-space indent, a newline at the end).
std::string GeneratedJsonText(const Scenario& scenario);

}  // namespace rlpos
