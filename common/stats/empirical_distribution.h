#pragma once
// Empirical CDF and CCDF of a sample: the paper plots the CCDF of aggregate throughput and the
// CDF of mean delay over the runs, one curve per position. Each gives one point per distinct
// value, in ascending x, to draw as a step function.
#include <vector>

namespace rlpos {

struct DistributionPoint {
  double x = 0;
  double p = 0;
};

// p = P(X <= x): the share of the sample at or below x (the last point has p = 1).
std::vector<DistributionPoint> EmpiricalCdf(std::vector<double> sample);

// p = P(X > x) = 1 - CDF: the share strictly above x (the last point has p = 0).
std::vector<DistributionPoint> EmpiricalCcdf(std::vector<double> sample);

}  // namespace rlpos
