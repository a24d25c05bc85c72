#include "worker/sim/portable_kernels.h"

#include <cstdlib>
#include <string>

namespace rlpos::sim {

// "default" is libtorch's kernel set built for the baseline x86-64 ISA. Prescott (SSE3) is the
// oldest x86-64 kernel set of Debian's OpenBLAS; every x86-64 CPU since 2005 runs it. SSE41
// caps oneDNN the same way (libtorch routes few CPU float ops to it, but may).
const char* const kPortableKernelSettings[4] = {
    "ATEN_CPU_CAPABILITY=default", "OPENBLAS_CORETYPE=Prescott", "ONEDNN_MAX_CPU_ISA=SSE41",
    "DNNL_MAX_CPU_ISA=SSE41"};

bool PinPortableKernels() {
  const char* native = std::getenv("RLPOS_NATIVE_KERNELS");
  if (native != nullptr && std::string(native) == "1")
    return false;
  for (const char* setting : kPortableKernelSettings) {
    const std::string text(setting);
    const std::size_t eq = text.find('=');
    setenv(text.substr(0, eq).c_str(), text.substr(eq + 1).c_str(), 1);
  }
  return true;
}

}  // namespace rlpos::sim
