#include "common/stats/descriptive.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "common/stats/student_t.h"

namespace rlpos {
namespace {

void CheckSample(const std::vector<double>& sample) {
  if (sample.empty())
    throw std::invalid_argument("empty sample");
  for (const double x : sample) {
    if (!std::isfinite(x))
      throw std::invalid_argument("sample holds a non-finite value");
  }
}

}  // namespace

double Mean(const std::vector<double>& sample) {
  CheckSample(sample);
  return std::accumulate(sample.begin(), sample.end(), 0.0) / static_cast<double>(sample.size());
}

double Median(std::vector<double> sample) {
  CheckSample(sample);
  const std::size_t mid = sample.size() / 2;
  std::nth_element(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(mid), sample.end());
  const double upper = sample[mid];
  if (sample.size() % 2 == 1)
    return upper;
  const double lower =
      *std::max_element(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

double Quantile(std::vector<double> sample, double q) {
  CheckSample(sample);
  if (!(q >= 0 && q <= 1))
    throw std::invalid_argument("quantile outside [0, 1]");
  std::sort(sample.begin(), sample.end());
  const double position = q * static_cast<double>(sample.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sample.size() - 1);
  return sample[below] + (position - static_cast<double>(below)) * (sample[above] - sample[below]);
}

double SampleStdDev(const std::vector<double>& sample) {
  const double mean = Mean(sample);
  if (sample.size() < 2)
    return 0.0;
  double sum = 0.0;
  for (const double x : sample)
    sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(sample.size() - 1));
}

ConfidenceInterval MeanConfidenceInterval(const std::vector<double>& sample, double level) {
  if (!(level > 0.0 && level < 1.0))
    throw std::invalid_argument("level must be in (0, 1)");
  ConfidenceInterval ci;
  ci.mean = Mean(sample);
  ci.n = sample.size();
  ci.level = level;
  if (ci.n < 2) {
    ci.half_width = std::numeric_limits<double>::quiet_NaN();
  } else {
    const double t = StudentTQuantile(1.0 - (1.0 - level) / 2.0, static_cast<double>(ci.n - 1));
    ci.half_width = t * SampleStdDev(sample) / std::sqrt(static_cast<double>(ci.n));
  }
  ci.low = ci.mean - ci.half_width;
  ci.high = ci.mean + ci.half_width;
  return ci;
}

double ChangePercent(double value, double baseline) {
  if (baseline == 0.0)
    return std::numeric_limits<double>::quiet_NaN();
  return 100.0 * (value - baseline) / std::fabs(baseline);
}

}  // namespace rlpos
