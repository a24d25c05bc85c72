#include "common/stats/empirical_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rlpos {
namespace {

// One point per distinct value: (x, number of values <= x); `above` flips it to the number > x.
std::vector<DistributionPoint> Steps(std::vector<double> sample, bool above) {
  if (sample.empty())
    throw std::invalid_argument("empty sample");
  for (const double x : sample) {
    if (!std::isfinite(x))
      throw std::invalid_argument("sample holds a non-finite value");
  }
  std::sort(sample.begin(), sample.end());
  const std::size_t n = sample.size();
  std::vector<DistributionPoint> points;
  for (std::size_t i = 0; i < n; ++i) {
    // Ties make one point, at the share of the last of them.
    if (i + 1 < n && sample[i + 1] == sample[i])
      continue;
    const std::size_t count = above ? n - (i + 1) : i + 1;
    points.push_back({sample[i], static_cast<double>(count) / static_cast<double>(n)});
  }
  return points;
}

}  // namespace

std::vector<DistributionPoint> EmpiricalCdf(std::vector<double> sample) {
  return Steps(std::move(sample), false);
}

std::vector<DistributionPoint> EmpiricalCcdf(std::vector<double> sample) {
  return Steps(std::move(sample), true);
}

}  // namespace rlpos
