#pragma once
// The random stream of one UE's mobility: its own engine, seeded from the scenario's seed, its
// RngRun and the UE's index, never ns-3's generators (drawing from those would shift every
// other random variable of a packet-level run). The transforms are written here (not <random>'s
// distributions, which differ between standard libraries).
#include <cstdint>
#include <random>

namespace rlpos {

class MobilityRandom {
 public:
  MobilityRandom(std::uint32_t seed, std::uint64_t run, std::size_t ue);

  // Uniform in [lo, hi).
  double Uniform(double lo, double hi);
  // Standard normal (Box-Muller).
  double Normal();
  // A direction, uniform in [0, 2 pi).
  double Angle();

 private:
  double Unit();  // uniform in [0, 1), 53 bits
  std::mt19937_64 engine_;
};

}  // namespace rlpos
