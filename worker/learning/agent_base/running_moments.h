#pragma once
// Running mean and variance (Welford) of a stream, e.g. the rewards an agent has seen.
#include <cstdint>
#include <iosfwd>

namespace rlpos {

class RunningMoments {
 public:
  void Add(double x);
  double Mean() const { return mean_; }
  double StdDev() const;
  // (x - mean) / std; a stream with no spread yet is only centred.
  float Standardise(double x) const;
  // Its exact state, for a checkpoint (state_stream.h).
  void SaveState(std::ostream& out) const;
  void LoadState(std::istream& in);

 private:
  std::int64_t count_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
};

}  // namespace rlpos
