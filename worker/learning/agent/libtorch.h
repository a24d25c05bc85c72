#pragma once
// The parts of libtorch the agents use: modules, Adam, gradient clipping and serialisation.
// Not <torch/torch.h>, which also brings the data loaders, the JIT and every module, and takes
// half again as long to parse in each translation unit that includes it.
#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/container/sequential.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/utils/clip_grad.h>
#include <torch/optim/adam.h>
#include <torch/serialize.h>
