#pragma once
// The float tensors of a network that libtorch saved with torch::save(module, file), read without
// libtorch. The file is untrusted (policy folders travel between machines), so the reader is
// bounded and strict: a zip archive of stored entries (stored_zip.h) whose data.pkl is a pickle
// of only the few opcodes and globals torch::save writes for a module of float parameters.
#include <cstdint>
#include <string>
#include <vector>

namespace rlpos {

struct SavedTensor {
  std::string name;  // dotted, as module->named_parameters() names it: "0.weight", "phi.2.bias"
  std::vector<std::int64_t> sizes;
  std::vector<float> values;  // row-major (contiguous)
};

// Every tensor of the module saved in `file` (its parameters, and buffers if it had any), in the
// order data.pkl lists them, which is the order of the module's named_parameters(). Throws
// std::runtime_error with a one-line message naming the file and what is wrong for anything else:
// a missing or oversized file, a broken or compressed archive, a failed CRC, an opcode or global
// outside the allowed few, a tensor of another type, non-contiguous or outside its storage.
std::vector<SavedTensor> ReadSavedTensors(const std::string& file);
// The same of a file's bytes already in memory, `name` standing for the file in messages.
std::vector<SavedTensor> ReadSavedTensorsFromBytes(std::string bytes, const std::string& name);

}  // namespace rlpos
