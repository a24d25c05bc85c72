#pragma once
// Random draws whose results are the same on every platform and standard library. The engine,
// std::mt19937_64, is specified bit for bit by the C++ standard; the distributions of <random>
// are not (libstdc++ and libc++ turn the same engine output into different numbers), so the
// transforms from engine output to a draw are written here, with integer arithmetic only.
#include <cstdint>
#include <random>
#include <vector>

namespace rlpos {

class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}

  // An integer uniform in [lo, hi] (lo <= hi), unbiased: engine outputs in the incomplete last
  // block of the range are rejected.
  long long UniformInt(long long lo, long long hi);
  // A multiple of 0.5 uniform in [lo, hi] (both multiples of 0.5): positions and sizes on a
  // half-metre grid are exact in binary, so they print the same everywhere.
  double UniformHalfMetres(double lo, double hi);
  // True with probability numerator / denominator.
  bool Chance(int numerator, int denominator);
  // An index drawn with probability weights[i] / sum(weights) (integer weights, sum > 0).
  std::size_t Weighted(const std::vector<int>& weights);

 private:
  std::mt19937_64 engine_;
};

}  // namespace rlpos
