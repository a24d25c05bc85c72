#pragma once
// Uniform draws that are the same on every standard library (std::uniform_real_distribution is
// implementation-defined): the classic envs' initial states are reproducible bytes.
#include <cstdint>
#include <random>

namespace rlpos {

// Uniform on [low, high) from the top 53 bits of one draw.
double UniformBetween(std::mt19937_64& rng, double low, double high);

}  // namespace rlpos
