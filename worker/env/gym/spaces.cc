#include "worker/env/gym/spaces.h"

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

Float32Clip::Float32Clip(const BoxSpace& box)
    : low_(box.low.begin(), box.low.end()), high_(box.high.begin(), box.high.end()) {}

void Float32Clip::Apply(const std::vector<double>& x, float* out) const {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const float v = static_cast<float>(x[i]);
    out[i] = v < low_[i] ? low_[i] : (v > high_[i] ? high_[i] : v);  // NaN compares false
  }
}

std::vector<float> Float32Clip::operator()(const std::vector<double>& x) const {
  std::vector<float> out(x.size());
  Apply(x, out.data());
  return out;
}

}  // namespace rlpos
