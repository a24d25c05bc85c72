#pragma once
// Gymnasium-style spaces: Discrete(n) and Box(low, high).
#include <cstddef>
#include <vector>

namespace rlpos {

struct DiscreteSpace {
  int n = 0;
  bool Contains(int action) const { return action >= 0 && action < n; }
};

struct BoxSpace {
  std::vector<double> low;
  std::vector<double> high;
  std::size_t Dim() const { return low.size(); }
  bool Contains(const std::vector<double>& x) const;
  // Affine map of [low, high] onto [-1, 1] per dimension (what a network should see).
  std::vector<float> Normalise(const std::vector<double>& x) const;
};

}  // namespace rlpos
