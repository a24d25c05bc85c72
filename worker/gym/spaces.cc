#include "worker/gym/spaces.h"

#include <cmath>

namespace rlpos {

bool BoxSpace::Contains(const std::vector<double>& x) const {
  if (x.size() != low.size())
    return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] >= low[i] && x[i] <= high[i]))
      return false;  // NaN too
  }
  return true;
}

std::vector<float> BoxSpace::Normalise(const std::vector<double>& x) const {
  std::vector<float> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(low[i]) || !std::isfinite(high[i])) {
      out[i] = static_cast<float>(x[i]);  // nothing to map onto [-1, 1]: passed as it is
      continue;
    }
    const double span = high[i] - low[i];
    out[i] = span > 0 ? static_cast<float>(2.0 * (x[i] - low[i]) / span - 1.0) : 0.0f;
  }
  return out;
}

}  // namespace rlpos
