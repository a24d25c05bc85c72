#pragma once
// The helpers the input makers of the place importer's fuzz share (place_inputs.cc,
// place_inputs_random.cc, place_inputs_geojson.cc): a number printed with a format, and a
// uniform draw.
#include <cstddef>
#include <cstdio>
#include <string>

#include "tests/fuzz/fuzz_input.h"

namespace rlpos::testing {

inline std::string Format(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// Uniform in [lo, hi].
inline double Uniform(FuzzInput& in, double lo, double hi) {
  constexpr std::size_t kSteps = std::size_t{1} << 30;
  return lo + (hi - lo) * static_cast<double>(in.Below(kSteps + 1)) / static_cast<double>(kSteps);
}

}  // namespace rlpos::testing
