#include "worker/learning/agent_base/running_moments.h"

#include <cmath>

#include "worker/learning/agent_base/state_stream.h"

namespace rlpos {

void RunningMoments::Add(double x) {
  ++count_;
  const double delta = x - mean_;
  mean_ += delta / static_cast<double>(count_);
  m2_ += delta * (x - mean_);
}

double RunningMoments::StdDev() const {
  return count_ > 1 ? std::sqrt(m2_ / static_cast<double>(count_ - 1)) : 0.0;
}

float RunningMoments::Standardise(double x) const {
  const double sd = StdDev();
  return static_cast<float>(sd > 1e-12 ? (x - mean_) / sd : x - mean_);
}

void RunningMoments::SaveState(std::ostream& out) const {
  state::Write(out, count_);
  state::Write(out, mean_);
  state::Write(out, m2_);
}

void RunningMoments::LoadState(std::istream& in) {
  count_ = state::Read<std::int64_t>(in);
  mean_ = state::Read<double>(in);
  m2_ = state::Read<double>(in);
}

}  // namespace rlpos
