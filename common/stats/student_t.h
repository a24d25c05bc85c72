#pragma once
// Student's t distribution, for confidence intervals of a mean over a few runs (the paper has 30
// per position, where the normal approximation would be ~4 % too narrow).

namespace rlpos {

// P(T <= t) for `df` > 0 degrees of freedom.
double StudentTCdf(double t, double df);

// The t with StudentTCdf(t, df) = p, for p in (0, 1). Throws std::invalid_argument otherwise.
double StudentTQuantile(double p, double df);

}  // namespace rlpos
