#include "common/stats/student_t.h"

#include <cmath>
#include <stdexcept>

namespace rlpos {
namespace {

constexpr double kTiny = 1e-300;

// One step of modified Lentz's method with the partial numerator aa: updates d and c (kept off
// zero) and returns the factor it applies to the fraction.
double LentzStep(double aa, double& c, double& d) {
  d = 1.0 + aa * d;
  if (std::fabs(d) < kTiny)
    d = kTiny;
  c = 1.0 + aa / c;
  if (std::fabs(c) < kTiny)
    c = kTiny;
  d = 1.0 / d;
  return d * c;
}

// Continued fraction of the regularized incomplete beta function (modified Lentz's method).
double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kEpsilon = 1e-15;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < kTiny)
    d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 1000; ++m) {
    const double m2 = 2.0 * m;
    h *= LentzStep(m * (b - m) * x / ((a + m2 - 1.0) * (a + m2)), c, d);
    const double step = LentzStep(-(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0)), c, d);
    h *= step;
    if (std::fabs(step - 1.0) < kEpsilon)
      break;
  }
  return h;
}

// I_x(a, b), the regularized incomplete beta function.
double RegularizedBeta(double a, double b, double x) {
  if (x <= 0.0)
    return 0.0;
  if (x >= 1.0)
    return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  // The continued fraction converges fast only on this side; use the symmetry otherwise.
  if (x < (a + 1.0) / (a + b + 2.0))
    return front * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - front * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double StudentTCdf(double t, double df) {
  if (!(df > 0.0))
    throw std::invalid_argument("degrees of freedom must be positive");
  if (std::isinf(t))
    return t > 0 ? 1.0 : 0.0;
  const double tail = 0.5 * RegularizedBeta(df / 2.0, 0.5, df / (df + t * t));
  return t > 0 ? 1.0 - tail : tail;
}

double StudentTQuantile(double p, double df) {
  if (!(p > 0.0 && p < 1.0))
    throw std::invalid_argument("quantile p must be in (0, 1)");
  if (!(df > 0.0))
    throw std::invalid_argument("degrees of freedom must be positive");
  if (p < 0.5)
    return -StudentTQuantile(1.0 - p, df);
  if (p == 0.5)
    return 0.0;
  double lo = 0.0;
  double hi = 1.0;
  while (StudentTCdf(hi, df) < p) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (StudentTCdf(mid, df) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace rlpos
