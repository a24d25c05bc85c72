#pragma once
// The scenario argument of the benches, with the one-line errors the commands give.
#include <optional>

#include "common/scenario/scenario.h"

// Loads `path` and, if `duration_s` is given, measures that many seconds after the warm-up.
// On a bad file or duration, prints "error: <what>: <problem>" and returns nothing.
std::optional<rlpos::Scenario> LoadBenchScenario(const char* path, const char* duration_s);
