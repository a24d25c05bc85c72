#include <gtest/gtest.h>

#include <cmath>

#include "common/stats/descriptive.h"
#include "common/stats/empirical_distribution.h"
#include "common/stats/student_t.h"

namespace rlpos {
namespace {

TEST(Descriptive, MeanAndMedian) {
  EXPECT_DOUBLE_EQ(Mean({1, 2, 3, 4, 10}), 4.0);
  EXPECT_DOUBLE_EQ(Median({10, 1, 3, 2, 4}), 3.0);
  EXPECT_DOUBLE_EQ(Median({4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(Median({7}), 7.0);
  EXPECT_DOUBLE_EQ(Median({5, 5, 1, 9}), 5.0);
}

TEST(Descriptive, SampleStdDev) {
  // Sum of squared deviations from the mean 5 is 32; n - 1 = 7.
  EXPECT_NEAR(SampleStdDev({2, 4, 4, 4, 5, 5, 7, 9}), std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_DOUBLE_EQ(SampleStdDev({3}), 0.0);
}

TEST(Descriptive, ConfidenceIntervalOfTheMean) {
  const ConfidenceInterval ci = MeanConfidenceInterval({2, 4, 4, 4, 5, 5, 7, 9});
  // t(0.975, 7) = 2.364624251592785; s = sqrt(32 / 7); n = 8.
  const double half = 2.364624251592785 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0);
  EXPECT_DOUBLE_EQ(ci.mean, 5.0);
  EXPECT_NEAR(ci.half_width, half, 1e-9);
  EXPECT_NEAR(half, 1.78748, 1e-5);
  EXPECT_NEAR(ci.low, 5.0 - half, 1e-9);
  EXPECT_NEAR(ci.high, 5.0 + half, 1e-9);
  EXPECT_EQ(ci.n, 8u);
  // 99 %: t(0.995, 3) = 5.840909309733; sample 1, 2, 3, 4: s = sqrt(5 / 3).
  const ConfidenceInterval wide = MeanConfidenceInterval({1, 2, 3, 4}, 0.99);
  EXPECT_NEAR(wide.half_width, 5.840909309733 * std::sqrt(5.0 / 3.0) / 2.0, 1e-8);
  EXPECT_TRUE(std::isnan(MeanConfidenceInterval({42}).half_width));
}

TEST(Descriptive, RejectsEmptyAndNonFinite) {
  EXPECT_THROW(Mean({}), std::invalid_argument);
  EXPECT_THROW(Median({}), std::invalid_argument);
  EXPECT_THROW(Mean({1, NAN}), std::invalid_argument);
  EXPECT_THROW(MeanConfidenceInterval({1, 2}, 1.0), std::invalid_argument);
}

TEST(Descriptive, QuantileInterpolatesBetweenOrderStatistics) {
  // numpy.quantile([1, 2, 3, 4, 10], q): 0.1 -> 1.4, 0.5 -> 3, 0.9 -> 7.6.
  EXPECT_DOUBLE_EQ(Quantile({10, 1, 3, 2, 4}, 0.0), 1.0);
  EXPECT_NEAR(Quantile({10, 1, 3, 2, 4}, 0.1), 1.4, 1e-12);
  EXPECT_DOUBLE_EQ(Quantile({10, 1, 3, 2, 4}, 0.5), 3.0);
  EXPECT_NEAR(Quantile({10, 1, 3, 2, 4}, 0.9), 7.6, 1e-12);
  EXPECT_DOUBLE_EQ(Quantile({10, 1, 3, 2, 4}, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(Quantile({4, 1, 3, 2}, 0.5), Median({4, 1, 3, 2}));
  EXPECT_DOUBLE_EQ(Quantile({0.7}, 0.1), 0.7);
  EXPECT_THROW(Quantile({}, 0.5), std::invalid_argument);
  EXPECT_THROW(Quantile({1, 2}, 1.5), std::invalid_argument);
  EXPECT_THROW(Quantile({1, 2}, NAN), std::invalid_argument);
}

TEST(Descriptive, ChangeAgainstBaseline) {
  EXPECT_DOUBLE_EQ(ChangePercent(110, 100), 10.0);
  EXPECT_DOUBLE_EQ(ChangePercent(75, 100), -25.0);
  EXPECT_DOUBLE_EQ(ChangePercent(-5, -10), 50.0);  // up from a negative baseline is positive
  EXPECT_TRUE(std::isnan(ChangePercent(1, 0)));
}

TEST(StudentT, QuantilesMatchTheTables) {
  EXPECT_NEAR(StudentTQuantile(0.975, 1), 12.706204736174698, 1e-9);
  EXPECT_NEAR(StudentTQuantile(0.975, 2), 4.302652729749464, 1e-9);
  EXPECT_NEAR(StudentTQuantile(0.975, 10), 2.228138851986274, 1e-9);
  EXPECT_NEAR(StudentTQuantile(0.975, 29), 2.045229642132703, 1e-9);  // 30 runs
  EXPECT_NEAR(StudentTQuantile(0.995, 4), 4.604094871349993, 1e-9);
  EXPECT_NEAR(StudentTQuantile(0.025, 29), -2.045229642132703, 1e-9);
  EXPECT_DOUBLE_EQ(StudentTQuantile(0.5, 3), 0.0);
  EXPECT_THROW(StudentTQuantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(StudentTQuantile(0.5, 0), std::invalid_argument);
}

TEST(StudentT, CdfClosedForms) {
  EXPECT_NEAR(StudentTCdf(1.0, 1), 0.75, 1e-12);  // Cauchy: 1/2 + atan(t)/pi
  EXPECT_NEAR(StudentTCdf(-2.0, 1), 0.5 + std::atan(-2.0) / M_PI, 1e-12);
  // df = 2: 1/2 + t / (2 sqrt(2 + t^2)).
  EXPECT_NEAR(StudentTCdf(1.5, 2), 0.5 + 1.5 / (2 * std::sqrt(2 + 2.25)), 1e-12);
  EXPECT_DOUBLE_EQ(StudentTCdf(0.0, 7), 0.5);
}

TEST(EmpiricalDistribution, CdfAndCcdfSteps) {
  const auto cdf = EmpiricalCdf({3, 1, 2, 2});
  ASSERT_EQ(cdf.size(), 3u);
  EXPECT_DOUBLE_EQ(cdf[0].x, 1);
  EXPECT_DOUBLE_EQ(cdf[0].p, 0.25);
  EXPECT_DOUBLE_EQ(cdf[1].x, 2);
  EXPECT_DOUBLE_EQ(cdf[1].p, 0.75);
  EXPECT_DOUBLE_EQ(cdf[2].x, 3);
  EXPECT_DOUBLE_EQ(cdf[2].p, 1.0);
  const auto ccdf = EmpiricalCcdf({3, 1, 2, 2});
  ASSERT_EQ(ccdf.size(), 3u);
  EXPECT_DOUBLE_EQ(ccdf[0].p, 0.75);
  EXPECT_DOUBLE_EQ(ccdf[1].p, 0.25);
  EXPECT_DOUBLE_EQ(ccdf[2].p, 0.0);
  const auto thirds = EmpiricalCcdf({10, 20, 30});
  EXPECT_DOUBLE_EQ(thirds[0].p, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(thirds[1].p, 1.0 / 3.0);
  EXPECT_THROW(EmpiricalCdf({}), std::invalid_argument);
  EXPECT_THROW(EmpiricalCcdf({1, INFINITY}), std::invalid_argument);
}

}  // namespace
}  // namespace rlpos
