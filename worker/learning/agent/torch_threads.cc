#include "worker/learning/agent/torch_threads.h"

#include <ATen/Parallel.h>

#include <cstdlib>

namespace rlpos {

int UseOneTorchThreadUnlessAsked() {
  // libtorch reads OMP_NUM_THREADS itself when its pool starts; only the default is ours.
  const char* asked = std::getenv("OMP_NUM_THREADS");
  if (asked == nullptr || *asked == '\0')
    at::set_num_threads(1);
  return at::get_num_threads();
}

}  // namespace rlpos
