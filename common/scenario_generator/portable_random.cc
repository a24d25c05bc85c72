#include "common/scenario_generator/portable_random.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rlpos {

long long PortableRandom::UniformInt(long long lo, long long hi) {
  if (hi < lo)
    throw std::logic_error("UniformInt: empty range");
  const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  if (span == std::numeric_limits<std::uint64_t>::max())
    return static_cast<long long>(engine_());
  const std::uint64_t range = span + 1;
  // 2^64 mod range outputs at the top would favour the low values: they are drawn again, so
  // that the accepted outputs [0, last] are a whole number of blocks of `range`.
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t last = max - (max % range + 1) % range;
  std::uint64_t x = engine_();
  while (x > last)
    x = engine_();
  return static_cast<long long>(static_cast<std::uint64_t>(lo) + x % range);
}

double PortableRandom::UniformHalfMetres(double lo, double hi) {
  const long long halves = UniformInt(std::llround(lo * 2), std::llround(hi * 2));
  return static_cast<double>(halves) / 2.0;
}

bool PortableRandom::Chance(int numerator, int denominator) {
  return UniformInt(0, denominator - 1) < numerator;
}

std::size_t PortableRandom::Weighted(const std::vector<int>& weights) {
  long long total = 0;
  for (int w : weights)
    total += w;
  long long draw = UniformInt(0, total - 1);
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (draw < weights[i])
      return i;
    draw -= weights[i];
  }
  return weights.size() - 1;
}

}  // namespace rlpos
