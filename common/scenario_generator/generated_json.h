#pragma once
// The document of a generated scenario: the keys in the shipped scenarios' order, only what the
// generator chose (the env and agent sections are left out, so the defaults apply), and whole
// numbers written as integers.
#include <string>

#include "common/scenario/scenario.h"

namespace rlpos {

// The JSON text (two-space indent, a newline at the end).
std::string GeneratedJsonText(const Scenario& scenario);

}  // namespace rlpos
