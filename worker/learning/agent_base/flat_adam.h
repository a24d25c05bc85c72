#pragma once
// Adam over one flat vector of parameters, with libtorch's update (torch::optim::Adam, no weight
// decay, no amsgrad): the same formula and float arithmetic, one loop instead of a dozen tensor
// ops per parameter tensor.
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace rlpos {

class FlatAdam {
 public:
  FlatAdam(std::size_t size, double learning_rate, double eps, double beta1 = 0.9,
           double beta2 = 0.999);
  // parameters -= the Adam step for `gradients` (both of the size given).
  void Step(std::vector<float>& parameters, const std::vector<float>& gradients);
  double LearningRate() const { return learning_rate_; }
  void SetLearningRate(double rate) { learning_rate_ = rate; }
  // Its exact state (moments, step count, rate), for a checkpoint (state_stream.h).
  void SaveState(std::ostream& out) const;
  void LoadState(std::istream& in);

 private:
  double learning_rate_;
  double eps_;
  double beta1_;
  double beta2_;
  std::int64_t steps_ = 0;
  std::vector<float> first_moment_;
  std::vector<float> second_moment_;
};

}  // namespace rlpos
