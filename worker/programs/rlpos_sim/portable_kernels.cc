#include "worker/programs/rlpos_sim/portable_kernels.h"

#include <cstdlib>
#include <string>

namespace rlpos::sim {

namespace {

struct KernelSetting {
  const char* variable;
  const char* value;
};

// "default" is libtorch's kernel set built for the baseline x86-64 ISA. Prescott (SSE3) is the
// oldest x86-64 kernel set of Debian's OpenBLAS; every x86-64 CPU since 2005 runs it. SSE41
// caps oneDNN the same way (libtorch routes few CPU float ops to it, but may).
constexpr KernelSetting kPortableKernels[] = {{"ATEN_CPU_CAPABILITY", "default"},
                                              {"OPENBLAS_CORETYPE", "Prescott"},
                                              {"ONEDNN_MAX_CPU_ISA", "SSE41"},
                                              {"DNNL_MAX_CPU_ISA", "SSE41"}};

}  // namespace

void PinPortableKernels() {
  const char* native = std::getenv("RLPOS_NATIVE_KERNELS");
  if (native != nullptr && std::string(native) == "1")
    return;
  for (const KernelSetting& setting : kPortableKernels)
    setenv(setting.variable, setting.value, 1);
}

}  // namespace rlpos::sim
