#include "worker/learning/classic_envs/uniform.h"

namespace rlpos {

double UniformBetween(std::mt19937_64& rng, double low, double high) {
  const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;  // [0, 1)
  return low + (high - low) * unit;
}

}  // namespace rlpos
