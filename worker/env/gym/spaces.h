#pragma once
// Gymnasium-style spaces: Discrete(n) and Box(low, high).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rlpos {

struct DiscreteSpace {
  int n = 0;
  bool Contains(int action) const { return action >= 0 && action < n; }
};

// Which actions of a Discrete space may be taken now (Gymnasium's "action_mask": 1 allowed,
// 0 not). Empty: every action is allowed.
using ActionMask = std::vector<std::uint8_t>;
inline bool Allowed(const ActionMask& mask, int action) {
  return mask.empty() || mask[static_cast<std::size_t>(action)] != 0;
}

// Where like slots lie in an observation vector (the UE slots of "ues"): `count` slots of `width`
// values from index `offset`. A slot holds something when its first value is > 0 (1 raw and 1
// normalised; an empty slot has 0 raw, -1 normalised).
struct SlotBlock {
  int offset = 0;
  int count = 0;
  int width = 0;
};

struct BoxSpace {
  std::vector<double> low;
  std::vector<double> high;
  std::size_t Dim() const { return low.size(); }
  bool Contains(const std::vector<double>& x) const;
  // Affine map of [low, high] onto [-1, 1] per dimension (what a network should see). A dimension
  // with an infinite bound (a velocity of Gymnasium's CartPole) is passed unscaled: the map
  // would send every value to one constant (or NaN).
  std::vector<float> Normalise(const std::vector<double>& x) const;
};

// An observation as the Python binding hands it out: float32, clipped to the space's bounds in
// float32 (NaN stays NaN), as np.clip(np.asarray(x, np.float32), low, high) gives it. What a
// policy trained through the binding saw, so what a policy exported from Python is fed.
class Float32Clip {
 public:
  explicit Float32Clip(const BoxSpace& box);
  // Writes x.size() floats to `out`.
  void Apply(const std::vector<double>& x, float* out) const;
  std::vector<float> operator()(const std::vector<double>& x) const;

 private:
  std::vector<float> low_, high_;
};

}  // namespace rlpos
