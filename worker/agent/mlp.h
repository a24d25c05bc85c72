#pragma once
// The small multilayer perceptrons the agents are made of, and what they do with them besides
// forward passes: copy, Polyak-average, load with a shape check.
#include <torch/torch.h>

#include <string>
#include <vector>

namespace rlpos {

// in -> hidden... (ReLU after each) -> out, no activation on the output.
torch::nn::Sequential MakeMlp(const std::vector<int>& hidden, int in, int out);

void CopyParameters(const torch::nn::Sequential& from, torch::nn::Sequential& to);
// to <- tau * from + (1 - tau) * to.
void SoftUpdate(const torch::nn::Sequential& from, torch::nn::Sequential& to, double tau);

// A 1 x n tensor of an observation (copied).
torch::Tensor Row(const std::vector<float>& values);

// Loads `file` into `into`, whose shapes it must match. Throws std::runtime_error naming the file
// when it is missing, not a saved network or of another shape.
void LoadNetwork(const std::string& file, torch::nn::Sequential& into,
                 const std::vector<int>& hidden, int in, int out);

}  // namespace rlpos
