#pragma once
// Per-position summaries over the runs of a campaign: mean, median, the confidence interval of
// the mean, and the change against the baseline. Every function takes the sample as is and
// throws std::invalid_argument for an empty sample or a non-finite value (filter undefined
// metrics, e.g. the delay of a run that received nothing, before calling).
#include <cstddef>
#include <vector>

namespace rlpos {

double Mean(const std::vector<double>& sample);
// The middle value; the mean of the two middle values for an even count.
double Median(std::vector<double> sample);
// The q-quantile, q in [0, 1], interpolated linearly between the order statistics at
// (n - 1) q (numpy's default, R's type 7): 0 is the minimum, 0.5 the median, 1 the maximum.
// Throws std::invalid_argument for q outside [0, 1] too.
double Quantile(std::vector<double> sample, double q);
// Sample standard deviation (n - 1 in the denominator); 0 for one value.
double SampleStdDev(const std::vector<double>& sample);

struct ConfidenceInterval {
  double mean = 0;
  double half_width = 0;  // NaN for a single value: one run says nothing about the spread
  double low = 0, high = 0;
  std::size_t n = 0;
  double level = 0.95;
};

// mean +- t(1 - (1 - level) / 2, n - 1) * s / sqrt(n).
ConfidenceInterval MeanConfidenceInterval(const std::vector<double>& sample, double level = 0.95);

// 100 * (value - baseline) / |baseline|: positive when value is above the baseline. NaN when
// the baseline is 0.
double ChangePercent(double value, double baseline);

}  // namespace rlpos
