#pragma once
// Where the running binary is: RLpos programs find their siblings (rlpos-sim, rlpos-worker,
// rlpos-coordinator) and data (share/rlpos) next to it, wherever the build or install is.
#include <string>

namespace rlpos {

// The folder of /proc/self/exe. Throws std::runtime_error if it cannot be read.
std::string ExecutableDir();

}  // namespace rlpos
