#include "common/mobility/mobility_random.h"

#include <cmath>

namespace rlpos {
namespace {

// SplitMix64's finaliser: nearby inputs (run 1, run 2; UE 0, UE 1) give unrelated seeds.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

MobilityRandom::MobilityRandom(std::uint32_t seed, std::uint64_t run, std::size_t ue)
    : engine_(Mix(Mix(Mix(0x6d6f62696c697479ULL ^ seed) ^ run) ^ static_cast<std::uint64_t>(ue))) {}

double MobilityRandom::Unit() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double MobilityRandom::Uniform(double lo, double hi) {
  return lo + (hi - lo) * Unit();
}

double MobilityRandom::Normal() {
  const double u = 1.0 - Unit();  // (0, 1]: log is finite
  const double v = Unit();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(kTwoPi * v);
}

double MobilityRandom::Angle() {
  return kTwoPi * Unit();
}

}  // namespace rlpos
