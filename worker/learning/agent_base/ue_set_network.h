#pragma once
// A network that takes the UE slots of an observation as a set (deep sets): each slot goes
// through one shared encoder phi (ReLU after each layer), the encodings of the present slots are
// averaged (no present slot: zeros), and the mean stands in for the slots' block in the input of
// a head rho, an MLP like MakeMlp's. The other values of the observation pass through as they
// are. The output thus does not depend on the order of the slots, nor on where the empty ones lie.
// In plain float like DenseNetwork, for the same reasons (dense_network.h): fixed summation
// orders, no FMA contraction. libtorch's twin (ue_set_module.h) initialises, saves and loads it.
#include <cstddef>
#include <vector>

#include "worker/env/gym/spaces.h"
#include "worker/learning/agent_base/dense_network.h"

namespace rlpos {

class UeSetNetwork {
 public:
  // input_size: the observation's width; slots: where the UE slots lie in it; encoder: phi's
  // widths (at least one); hidden, out: rho's. std::invalid_argument for slots outside the input
  // or widths that are not positive.
  UeSetNetwork(int input_size, SlotBlock slots, const std::vector<int>& encoder,
               const std::vector<int>& hidden, int out);

  int InputSize() const { return input_size_; }
  int OutputSize() const { return head_.OutputSize(); }
  const SlotBlock& Slots() const { return slots_; }
  // phi: slot width -> encoder..., and rho: (input - slots + encoding) -> hidden... -> out.
  std::vector<int> EncoderSizes() const;
  std::vector<int> HeadSizes() const;

  // phi's parameters (DenseNetwork's layout), then rho's. A change made through the non-const
  // reference is seen by the next Forward.
  std::vector<float>& Parameters() {
    stale_ = true;
    return parameters_;
  }
  const std::vector<float>& Parameters() const { return parameters_; }
  std::size_t EncoderParameterCount() const { return encoder_.Parameters().size(); }

  // out[rows][OutputSize()] for x[rows][InputSize()], both row-major.
  void Forward(const float* x, int rows, float* out);
  // d_out[rows][OutputSize()]: d loss / d output for the rows of the last Forward. Sets
  // Gradients() (the layout of Parameters()).
  void Backward(const float* d_out);
  std::vector<float>& Gradients() { return gradients_; }
  const std::vector<float>& Gradients() const { return gradients_; }

 private:
  // The sub-networks' parameters from parameters_, if they changed.
  void Sync();

  int input_size_;
  SlotBlock slots_;
  DenseNetwork encoder_;  // phi, one row per present slot
  DenseNetwork head_;     // rho
  std::vector<float> parameters_;
  std::vector<float> gradients_;
  bool stale_ = true;
  // The last Forward's: each row's count of present slots, the present slots (rows in order,
  // slots in order within a row), their encodings, and rho's input.
  int rows_ = 0;
  std::vector<int> present_;
  std::vector<float> slot_inputs_;
  std::vector<float> encodings_;
  std::vector<float> head_inputs_;
  std::vector<float> d_head_inputs_;
  std::vector<float> d_encodings_;
};

}  // namespace rlpos
