#include "common/phy/dcf_contention.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace rlpos {
namespace {

// Bianchi's tau for a conditional collision probability p, in the form without the 0/0 at
// p = 1/2: tau = 2 / (1 + W + p W sum_{k<m} (2p)^k), W = CWmin + 1, m backoff stages.
double Tau(double p, double w, int stages) {
  double sum = 0.0, term = 1.0;
  for (int k = 0; k < stages; ++k, term *= 2 * p)
    sum += term;
  return 2.0 / (1.0 + w + p * w * sum);
}

}  // namespace

int BackoffStages(int cw_min, int cw_max) {
  return std::max(0, static_cast<int>(std::lround(std::log2((cw_max + 1.0) / (cw_min + 1.0)))));
}

double BackoffTau(double p, int cw_min, int cw_max) {
  return Tau(p, cw_min + 1.0, BackoffStages(cw_min, cw_max));
}

double BackoffTauAtStages(double p, int cw_min, int stages) {
  return Tau(p, cw_min + 1.0, stages);
}

namespace {

DcfContention Solve(double n, int cw_min, int cw_max) {
  const double w = cw_min + 1.0;
  const int stages = BackoffStages(cw_min, cw_max);
  // p = 1 - (1 - tau(p))^(n-1): the left side grows and the right side falls with p, so the
  // fixed point is unique; bisection finds it. Once a step leaves both ends as they were,
  // every later step would too: stopping there gives the bits of all 100 steps.
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 100; ++k) {
    const double p = 0.5 * (lo + hi);
    const double rhs = 1.0 - std::pow(1.0 - Tau(p, w, stages), n - 1.0);
    double& end = rhs > p ? lo : hi;
    if (end == p)
      break;
    end = p;
  }
  DcfContention c;
  c.collision_probability = 0.5 * (lo + hi);
  c.tau = Tau(c.collision_probability, w, stages);
  const double idle = std::pow(1.0 - c.tau, n);
  const double success = n * c.tau * std::pow(1.0 - c.tau, n - 1.0);
  c.idle_slots_per_success = idle / success;
  c.collisions_per_success = (1.0 - idle - success) / success;
  return c;
}

// The airtime model asks for the same few station counts over and over (on a full channel, the
// number of stations), and a solution costs some sixty pow calls. A small memo per thread, keyed
// by the exact bits of its inputs, gives the same numbers at once and never grows.
struct DcfMemoEntry {
  bool filled = false;
  std::uint64_t stations_bits = 0;
  int cw_min = 0, cw_max = 0;
  DcfContention value;
};
constexpr std::size_t kDcfMemoSlots = 16;

}  // namespace

DcfContention SaturatedDcf(double stations, int cw_min, int cw_max) {
  const double n = std::max(1.0, stations);
  std::uint64_t bits;
  std::memcpy(&bits, &n, sizeof bits);
  thread_local std::array<DcfMemoEntry, kDcfMemoSlots> memo{};
  // Station counts are small whole numbers or fractions of one: fold the mantissa's top bits.
  const std::uint64_t h = (bits >> 40) ^ (bits >> 20) ^ bits;
  DcfMemoEntry& e = memo[static_cast<std::size_t>((h ^ (h >> 7)) % kDcfMemoSlots)];
  if (e.filled && e.stations_bits == bits && e.cw_min == cw_min && e.cw_max == cw_max)
    return e.value;
  e = {true, bits, cw_min, cw_max, Solve(n, cw_min, cw_max)};
  return e.value;
}

}  // namespace rlpos
